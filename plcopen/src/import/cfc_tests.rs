//! The CFC import (docs/plcopen-xml.md §4.5–4.6): CODESYS's CFC, Rivet's marked FBD bodies and
//! any FBD graph.
