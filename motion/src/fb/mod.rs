//! The PLCopen single-axis function blocks as plain structs: public input fields named after
//! the PLCopen inputs, public output fields, and a `call` that the runtime makes once per cycle
//! with the kernel and the axis the instance's `Axis` input refers to.
