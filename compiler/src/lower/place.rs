//! The place of a finding in an LD or FBD body: POU, body, network, element and pin.

use std::fmt;

use project_model::{ElementId, TextTarget};

/// Where in a graphical body a finding is: what the editor marks and the command line prints.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct ElementPlace {
    /// The POU's name.
    pub pou: String,
    /// Which body of the POU (its own, a method's, an accessor's or an action's).
    pub target: TextTarget,
    /// The network's index in the body, from 0 (shown from 1, as the editor numbers them).
    pub network: usize,
    /// The element's stable id; `None` when the finding is about the network itself (its
    /// label).
    pub element: Option<ElementId>,
    /// The pin of a box the finding is about, if any (`PT`).
    pub pin: Option<String>,
}

impl fmt::Display for ElementPlace {
    /// `POU:network:element` (`Main:2:7`), the body's member after the POU (`FB.Reset:1:3`,
    /// `FB.Speed.get:1:3`) and the pin after the element (`Main:2:7.PT`); the network counts
    /// from 1 and the element is its id, or `-` for the network itself.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.pou)?;
        match &self.target {
            TextTarget::Pou(_) => {}
            TextTarget::Method { method: member, .. }
            | TextTarget::Action { action: member, .. }
            | TextTarget::Transition {
                transition: member, ..
            } => write!(f, ".{member}")?,
            TextTarget::Property { property, get, .. } => {
                write!(f, ".{property}.{}", if *get { "get" } else { "set" })?;
            }
        }
        write!(f, ":{}:", self.network + 1)?;
        match self.element {
            Some(element) => write!(f, "{}", element.0)?,
            None => write!(f, "-")?,
        }
        if let Some(pin) = &self.pin {
            write!(f, ".{pin}")?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_place_reads_pou_network_element_and_pin() {
        let place = ElementPlace {
            pou: "FB".into(),
            target: TextTarget::Action {
                pou: "FB".into(),
                action: "Reset".into(),
            },
            network: 1,
            element: Some(ElementId(7)),
            pin: Some("PT".into()),
        };
        assert_eq!(place.to_string(), "FB.Reset:2:7.PT");
        let label = ElementPlace {
            target: TextTarget::Pou("FB".into()),
            element: None,
            pin: None,
            ..place
        };
        assert_eq!(label.to_string(), "FB:2:-");
    }
}
