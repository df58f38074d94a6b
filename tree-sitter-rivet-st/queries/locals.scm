; Scopes, definitions and references, for highlighting a name the same way wherever it is
; used in its POU.

; Scopes

[
  (source_file)
  (program_declaration)
  (function_block_declaration)
  (function_declaration)
  (method_declaration)
  (property_declaration)
  (action_declaration)
  (interface_declaration)
] @local.scope

; Definitions

(var_declaration
  name: (identifier) @local.definition)

(enum_value
  name: (identifier) @local.definition)

(label_statement
  label: (identifier) @local.definition)

(step
  name: (identifier) @local.definition)

; References

(identifier) @local.reference
