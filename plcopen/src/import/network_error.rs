//! What makes an LD or FBD body impossible to turn into Rivet networks.

/// A fault of an LD or FBD graph; the [`super::ImportError`] that carries it names the object's
/// line, column and element path.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum NetworkError {
    /// A continuation reads a connector name no connector of the body has.
    #[error("the continuation `{name}` has no connector of that name in its body")]
    MissingConnector {
        /// The name read.
        name: String,
    },
    /// Two connectors of one body have the same name, so a continuation could read either.
    #[error(
        "the connector `{name}` is defined twice in its body (lines {first_line} and {second_line})"
    )]
    DuplicateConnector {
        /// The name.
        name: String,
        /// Line of the first connector.
        first_line: u32,
        /// Line of the second connector.
        second_line: u32,
    },
    /// Connectors and continuations that lead back to themselves without an element between, or
    /// a chain of more than 256 of them.
    #[error(
        "the connector `{name}` leads back to itself through continuations, or through more than 256"
    )]
    ConnectorLoop {
        /// The name of a connector on the loop.
        name: String,
    },
    /// An element that needs power or a value on its left has no connection there.
    #[error("the {element} has nothing connected before it")]
    NothingBefore {
        /// The element name, such as `coil`.
        element: &'static str,
    },
    /// A connection names an output pin the block does not have.
    #[error(
        "the connection reads the output `{pin}` of the block `{block}`, which has no such output"
    )]
    UnknownPin {
        /// The pin named.
        pin: String,
        /// The block's type name.
        block: String,
    },
    /// A block names one pin twice.
    #[error("the block `{block}` has two pins named `{pin}`")]
    DuplicatePin {
        /// The pin.
        pin: String,
        /// The block's type name.
        block: String,
    },
    /// A coil whose attributes ask for two kinds at once (negated and set, edge and reset, …).
    #[error("the coil of `{variable}` is {attributes}; a Rivet coil has one kind")]
    ConflictingCoil {
        /// The variable written.
        variable: String,
        /// The attributes written, as words.
        attributes: String,
    },
    /// An `inOutVariable` with a negation, edge or storage attribute.
    #[error(
        "the inOutVariable `{variable}` has a negation, edge or storage attribute, which Rivet's networks cannot hold"
    )]
    InOutAttributes {
        /// The variable.
        variable: String,
    },
    /// A rung that is not series-parallel and cannot be expanded, because an element other
    /// than a contact lies on several of its paths.
    #[error(
        "the rung is not series-parallel and a {element} lies on several of its paths, so it cannot be expanded into branches"
    )]
    NotSeriesParallel {
        /// The element name of what would be duplicated (`block`).
        element: &'static str,
    },
    /// A rung whose expansion into series-parallel branches would have too many paths.
    #[error("the rung is not series-parallel and has more than {limit} paths to expand")]
    TooManyPaths {
        /// The limit.
        limit: usize,
    },
    /// Boxes nested in box inputs, or output branches, deeper than a Rivet body may hold.
    #[error("the network nests boxes or branches more than {limit} levels deep")]
    TooDeep {
        /// The limit (`project_model::MAX_NETWORK_NESTING`).
        limit: usize,
    },
    /// Rivet's own `…/networks` entry cannot be read.
    #[error("Rivet's networks entry is unreadable: {0}")]
    NetworksEntry(String),
    /// The networks break a rule of Rivet's LD/FBD bodies (`project_model::network_problems`).
    #[error("the converted networks break a rule: {0}")]
    Problem(String),
}
