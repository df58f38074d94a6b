; Highlighting for IEC 61131-3 Structured Text.
;
; The first pattern that captures a node wins (the tree-sitter-highlight convention), so the
; specific patterns come first and the plain `(identifier) @variable` comes last.

; Comments and pragmas

(comment) @comment

(pragma) @attribute

; Literals

[
  (integer)
  (real)
] @number

[
  (time_literal)
  (date_literal)
] @number

[
  (string)
  (wide_string)
] @string

(boolean) @constant.builtin

(direct_address) @constant

((typed_literal
  type: (identifier) @type.builtin)
  (#match? @type.builtin "^(?i)(BOOL|BYTE|WORD|DWORD|LWORD|SINT|INT|DINT|LINT|USINT|UINT|UDINT|ULINT|REAL|LREAL|STRING|WSTRING|CHAR|WCHAR)$"))

(typed_literal
  type: (identifier) @type)

(typed_literal
  value: (identifier) @constant)

(enum_value
  name: (identifier) @constant)

; Declared names

(program_declaration
  name: (identifier) @type)

(function_block_declaration
  name: (identifier) @type)

(interface_declaration
  name: (identifier) @type)

(type_definition
  name: (identifier) @type)

(function_declaration
  name: (identifier) @function)

(method_declaration
  name: (identifier) @function.method)

(action_declaration
  name: (identifier) @function.method)

(property_declaration
  name: (identifier) @property)

(var_declaration
  name: (identifier) @variable)

(var_declaration
  name: (qualified_name
    (identifier) @variable))

(step
  name: (identifier) @label)

(transition
  name: (identifier) @label)

(step_list
  (identifier) @label)

(label_statement
  label: (identifier) @label)

(jump_statement
  label: (identifier) @label)

; Types

; The elementary types of IEC 61131-3, whatever their case.
((named_type
  name: (identifier) @type.builtin)
  (#match? @type.builtin "^(?i)(BOOL|BYTE|WORD|DWORD|LWORD|SINT|INT|DINT|LINT|USINT|UINT|UDINT|ULINT|REAL|LREAL|TIME|LTIME|DATE|LDATE|TIME_OF_DAY|TOD|LTIME_OF_DAY|LTOD|DATE_AND_TIME|DT|LDATE_AND_TIME|LDT|CHAR|WCHAR|BIT|__XWORD|__UXINT|__XINT|ANY|ANY_NUM|ANY_INT|ANY_REAL|ANY_BIT|ANY_STRING|ANY_DATE)$"))

(named_type
  name: (identifier) @type)

(named_type
  name: (qualified_name
    (identifier) @type))

(extends_clause
  (identifier) @type)

(implements_clause
  (identifier) @type)

(program_configuration
  type: (identifier) @type)

(string_type
  [
    "STRING"
    "WSTRING"
  ] @type.builtin)

; Calls, members and arguments

(call_expression
  function: (identifier) @function.call)

(call_expression
  function: (field_expression
    field: (identifier) @function.method.call))

(field_expression
  field: (identifier) @property)

(named_argument
  name: (identifier) @variable.parameter)

(output_argument
  name: (identifier) @variable.parameter)

(field_initializer
  name: (identifier) @property)

[
  (this)
  (super)
] @variable.builtin

; Operators

[
  ":="
  "S="
  "R="
  "REF="
  "?="
  "=>"
  "+"
  "-"
  "*"
  "/"
  "**"
  "="
  "<>"
  "<"
  "<="
  ">"
  ">="
  "&"
  "^"
  ".."
] @operator

[
  "AND"
  "AND_THEN"
  "OR"
  "OR_ELSE"
  "XOR"
  "NOT"
  "MOD"
] @keyword.operator

; Keywords

[
  "PROGRAM"
  "END_PROGRAM"
  "FUNCTION"
  "END_FUNCTION"
  "FUNCTION_BLOCK"
  "END_FUNCTION_BLOCK"
  "METHOD"
  "END_METHOD"
  "PROPERTY"
  "END_PROPERTY"
  "GET"
  "END_GET"
  "SET"
  "END_SET"
  "ACTION"
  "END_ACTION"
  "INTERFACE"
  "END_INTERFACE"
  "EXTENDS"
  "IMPLEMENTS"
  "TYPE"
  "END_TYPE"
  "STRUCT"
  "END_STRUCT"
  "UNION"
  "END_UNION"
  "ARRAY"
  "OF"
  "POINTER"
  "REFERENCE"
  "REF_TO"
  "TO"
  "AT"
  "CONFIGURATION"
  "END_CONFIGURATION"
  "RESOURCE"
  "END_RESOURCE"
  "ON"
  "TASK"
  "WITH"
  "VAR"
  "VAR_INPUT"
  "VAR_OUTPUT"
  "VAR_IN_OUT"
  "VAR_GLOBAL"
  "VAR_EXTERNAL"
  "VAR_TEMP"
  "VAR_STAT"
  "VAR_INST"
  "VAR_CONFIG"
  "VAR_ACCESS"
  "END_VAR"
  "INITIAL_STEP"
  "STEP"
  "END_STEP"
  "TRANSITION"
  "FROM"
  "END_TRANSITION"
] @keyword

[
  "ABSTRACT"
  "FINAL"
  "PUBLIC"
  "PRIVATE"
  "PROTECTED"
  "INTERNAL"
  "CONSTANT"
  "RETAIN"
  "NON_RETAIN"
  "PERSISTENT"
  "R_EDGE"
  "F_EDGE"
  "READ_ONLY"
  "READ_WRITE"
] @keyword.modifier

[
  "IF"
  "THEN"
  "ELSIF"
  "ELSE"
  "END_IF"
  "CASE"
  "END_CASE"
] @keyword.conditional

[
  "FOR"
  "BY"
  "DO"
  "END_FOR"
  "WHILE"
  "END_WHILE"
  "REPEAT"
  "UNTIL"
  "END_REPEAT"
  "EXIT"
  "CONTINUE"
] @keyword.repeat

[
  "RETURN"
  "JMP"
] @keyword.return

; Punctuation

[
  "("
  ")"
  "["
  "]"
] @punctuation.bracket

[
  ";"
  ","
  "."
  ":"
  "#"
] @punctuation.delimiter

; Everything else that is named is a variable.

(identifier) @variable
