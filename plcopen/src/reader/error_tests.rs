//! Bad input: each error names the line, column and element path.
