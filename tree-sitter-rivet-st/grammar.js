/**
 * @file Tree-sitter grammar for IEC 61131-3 Structured Text, CODESYS dialect.
 *
 * The grammar follows Rivet's own parser (`compiler::syntax`), which stays the only source of
 * diagnostics: it accepts everything that parser accepts, so the editor can highlight, fold
 * and match blocks incrementally. Keywords are case-insensitive; words the compiler does not
 * reserve (STEP, INITIAL_STEP, TRANSITION, GET, SET) are recognised by `src/scanner.c` only
 * where the compiler would take them as keywords.
 */

/* eslint-disable arrow-parens, camelcase */

/** IEC priorities, weakest first; every binary operator is left-associative. */
const PREC = {
  or: 1,
  xor: 2,
  and: 3,
  equality: 4,
  comparison: 5,
  additive: 6,
  multiplicative: 7,
  unary: 8,
  power: 9,
  postfix: 10,
  name: 11,
  repeat: 12,
};

/**
 * A case-insensitive regular expression for `word`.
 * @param {string} word
 * @returns {RegExp}
 */
function caseless(word) {
  return new RegExp(
    word
      .split('')
      .map((c) => (/[a-zA-Z]/.test(c) ? `[${c.toLowerCase()}${c.toUpperCase()}]` : c))
      .join(''),
  );
}

/**
 * A keyword, matched without regard to case and shown in the tree as its upper-case spelling.
 * @param {string} word
 * @returns {AliasRule}
 */
function kw(word) {
  return alias(caseless(word), word);
}

/**
 * One or more `rule`s separated by commas.
 * @param {RuleOrLiteral} rule
 * @returns {SeqRule}
 */
function commaSep1(rule) {
  return seq(rule, repeat(seq(',', rule)));
}

/** The sections that may open a variable block, global ones last. */
const LOCAL_VAR_SECTIONS = [
  'VAR',
  'VAR_INPUT',
  'VAR_OUTPUT',
  'VAR_IN_OUT',
  'VAR_EXTERNAL',
  'VAR_TEMP',
  'VAR_STAT',
  'VAR_INST',
  'VAR_ACCESS',
];
const GLOBAL_VAR_SECTIONS = ['VAR_GLOBAL', 'VAR_CONFIG'];

/**
 * A variable block opened by one of `sections`.
 * @param {GrammarSymbols<string>} $
 * @param {string[]} sections
 * @returns {SeqRule}
 */
function varBlock($, sections) {
  return seq(
    choice(...sections.map(kw)),
    repeat(choice(kw('CONSTANT'), kw('RETAIN'), kw('NON_RETAIN'), kw('PERSISTENT'))),
    repeat($.var_declaration),
    kw('END_VAR'),
  );
}

module.exports = grammar({
  name: 'rivet_st',

  word: $ => $.identifier,

  extras: $ => [/\s/, $.comment, $.pragma],

  externals: $ => [
    $.comment,
    $._step_keyword,
    $._initial_step_keyword,
    $._transition_keyword,
    $._get_keyword,
    $._set_keyword,
    // Never produced: when the parser asks for it, it is recovering from an error.
    $._error_sentinel,
  ],

  supertypes: $ => [$._expression, $._statement, $._literal],

  inline: $ => [$._name_ref, $._declared_name, $._case_label],

  conflicts: $ => [
    // After a statement of a CASE branch, an identifier may start the next statement or the
    // labels of the next branch; the token after the label's expression decides.
    [$.case_branch],
    // In a declaration part, a method may be the last one, left open at the end of the text.
    [$._interface_head],
  ],

  rules: {
    // A whole source file, a POU body as a project stores it (statements only), or a
    // declaration part stored apart from its body (as CODESYS and TwinCAT keep them).
    source_file: $ => choice(
      repeat($._item),
      repeat1($._statement_or_label),
      $._declaration_part,
    ),

    _item: $ => choice(
      $.program_declaration,
      $.function_block_declaration,
      $.function_declaration,
      $.method_declaration,
      $.property_declaration,
      $.action_declaration,
      $.interface_declaration,
      $.type_declaration,
      $.global_var_declaration,
      $.configuration_declaration,
    ),

    // A POU, method, property, action or interface without its end keyword, or bare variable
    // blocks (a property accessor's declarations): what a declaration part stored apart from
    // its body holds. Like the compiler, it may run on into statements up to the end of the
    // text.
    _declaration_part: $ => choice(
      alias($._program_declaration_part, $.program_declaration),
      alias($._function_block_declaration_part, $.function_block_declaration),
      alias($._function_declaration_part, $.function_declaration),
      alias($._interface_declaration_part, $.interface_declaration),
      $._member_declaration_part,
      seq(alias($._local_var_block, $.var_block), repeat($.var_block)),
    ),
    _program_declaration_part: $ => seq(
      $._program_head,
      optional($._var_blocks),
      optional(alias($._pou_body, $.body)),
      optional($._member_declaration_part),
    ),
    _function_block_declaration_part: $ => seq(
      $._function_block_head,
      optional($._var_blocks),
      optional(alias($._pou_body, $.body)),
      optional($._member_declaration_part),
    ),
    _function_declaration_part: $ => seq(
      $._function_head,
      optional($._var_blocks),
      optional(alias($._pou_body, $.body)),
      optional($._member_declaration_part),
    ),
    _interface_declaration_part: $ => seq(
      $._interface_head,
      optional($._member_declaration_part),
    ),
    // A method, property or action whose end keyword is missing at the end of the text.
    _member_declaration_part: $ => choice(
      alias($._method_declaration_part, $.method_declaration),
      alias($._property_declaration_part, $.property_declaration),
      alias($._action_declaration_part, $.action_declaration),
    ),
    _method_declaration_part: $ => seq($._method_head, optional($._var_blocks), optional($.body)),
    _property_declaration_part: $ => seq(
      $._property_head,
      optional($._var_blocks),
      repeat($.property_accessor),
      optional($.body),
    ),
    _action_declaration_part: $ => seq($._action_head, optional($.body)),

    // ---------------------------------------------------------------- POUs and members

    program_declaration: $ => seq(
      $._program_head,
      optional($._var_blocks),
      optional(alias($._pou_body, $.body)),
      kw('END_PROGRAM'),
    ),
    _program_head: $ => seq(kw('PROGRAM'), $._pou_signature),

    function_block_declaration: $ => seq(
      $._function_block_head,
      optional($._var_blocks),
      optional(alias($._pou_body, $.body)),
      kw('END_FUNCTION_BLOCK'),
    ),
    _function_block_head: $ => seq(kw('FUNCTION_BLOCK'), $._pou_signature),

    function_declaration: $ => seq(
      $._function_head,
      optional($._var_blocks),
      optional(alias($._pou_body, $.body)),
      kw('END_FUNCTION'),
    ),
    _function_head: $ => seq(kw('FUNCTION'), $._pou_signature),

    // Modifiers, name, return type, inheritance and the `;` CODESYS tolerates after them.
    _pou_signature: $ => prec.right(1, seq(
      repeat($.modifier),
      field('name', $._declared_name),
      optional($.return_type),
      optional($.extends_clause),
      optional($.implements_clause),
      optional(';'),
    )),

    modifier: _ => choice(
      kw('ABSTRACT'),
      kw('FINAL'),
      kw('PUBLIC'),
      kw('PRIVATE'),
      kw('PROTECTED'),
      kw('INTERNAL'),
    ),

    return_type: $ => seq(':', field('type', $._type)),

    extends_clause: $ => seq(kw('EXTENDS'), commaSep1($._name_ref)),

    implements_clause: $ => seq(kw('IMPLEMENTS'), commaSep1($._name_ref)),

    // Statements of a POU, with methods, properties and actions in between (textual SFC
    // interleaves steps, transitions and actions).
    _pou_body: $ => repeat1(choice(
      $._statement_or_label,
      $.method_declaration,
      $.property_declaration,
      $.action_declaration,
    )),

    body: $ => repeat1($._statement_or_label),

    method_declaration: $ => seq(
      $._method_head,
      optional($._var_blocks),
      optional($.body),
      kw('END_METHOD'),
    ),
    _method_head: $ => seq(kw('METHOD'), $._member_signature),

    property_declaration: $ => seq(
      $._property_head,
      optional($._var_blocks),
      repeat($.property_accessor),
      optional($.body),
      kw('END_PROPERTY'),
    ),
    _property_head: $ => seq(kw('PROPERTY'), $._member_signature),

    _member_signature: $ => prec.right(1, seq(
      repeat($.modifier),
      field('name', $._declared_name),
      optional($.return_type),
      optional(';'),
    )),

    // `GET … END_GET` or `SET … END_SET`, a property accessor written inline.
    property_accessor: $ => prec.right(1, seq(
      choice(
        seq(
          alias($._get_keyword, 'GET'),
          optional(';'),
          optional($._var_blocks),
          optional($.body),
          kw('END_GET'),
        ),
        seq(
          alias($._set_keyword, 'SET'),
          optional(';'),
          optional($._var_blocks),
          optional($.body),
          kw('END_SET'),
        ),
      ),
      optional(';'),
    )),

    action_declaration: $ => seq($._action_head, optional($.body), kw('END_ACTION')),
    _action_head: $ => seq(kw('ACTION'), field('name', $._declared_name), optional(':')),

    interface_declaration: $ => seq(
      $._interface_head,
      kw('END_INTERFACE'),
    ),
    _interface_head: $ => seq(
      kw('INTERFACE'),
      field('name', $._declared_name),
      optional($.extends_clause),
      optional($.implements_clause),
      repeat(choice($.method_declaration, $.property_declaration)),
    ),

    // ---------------------------------------------------------------- types

    type_declaration: $ => seq(
      kw('TYPE'),
      repeat(seq($.type_definition, optional(';'))),
      kw('END_TYPE'),
    ),

    type_definition: $ => seq(
      field('name', $.identifier),
      optional($.extends_clause),
      optional($.implements_clause),
      ':',
      field('type', choice($.struct_type, $.union_type, $.enum_type, $._non_enum_type)),
      optional($.initializer),
    ),

    struct_type: $ => seq(kw('STRUCT'), repeat($.var_declaration), kw('END_STRUCT')),

    union_type: $ => seq(kw('UNION'), repeat($.var_declaration), kw('END_UNION')),

    // An enumeration with its base type, `(Idle := 0, Running) DINT`; only a type
    // declaration can give the base type.
    enum_type: $ => prec.right(seq(
      $._enum_values,
      optional(field('base', $._non_enum_type)),
    )),

    _enum_values: $ => seq('(', commaSep1($.enum_value), ')'),

    enum_value: $ => seq(
      field('name', $.identifier),
      optional(seq(':=', field('value', $._expression))),
    ),

    _type: $ => choice($._non_enum_type, alias($._enum_values, $.enum_type)),

    _non_enum_type: $ => choice(
      $.named_type,
      $.string_type,
      $.array_type,
      $.pointer_type,
      $.reference_type,
    ),

    // A named type, a subrange `INT(0..100)`, or an FB instance with initialisation
    // arguments `FB_Logger(Results)`.
    named_type: $ => prec.right(seq(
      field('name', $._name_ref),
      optional(choice($.subrange, $.argument_list)),
    )),

    subrange: $ => seq(
      '(',
      field('lower', $._expression),
      '..',
      field('upper', $._expression),
      ')',
    ),

    string_type: $ => prec.right(seq(
      choice(kw('STRING'), kw('WSTRING')),
      optional(choice(
        seq('(', field('length', $._expression), ')'),
        seq('[', field('length', $._expression), ']'),
      )),
    )),

    array_type: $ => seq(
      kw('ARRAY'),
      '[',
      commaSep1($.array_range),
      ']',
      kw('OF'),
      field('element', $._type),
    ),

    // `1..10`, `*`, or matiec's open `1..`.
    array_range: $ => choice(
      '*',
      seq(field('lower', $._expression), '..', optional(field('upper', $._expression))),
    ),

    pointer_type: $ => seq(kw('POINTER'), kw('TO'), field('target', $._type)),

    reference_type: $ => choice(
      seq(kw('REFERENCE'), kw('TO'), field('target', $._type)),
      seq(kw('REF_TO'), field('target', $._type)),
    ),

    // ---------------------------------------------------------------- variables

    global_var_declaration: $ => prec.right(seq(
      alias($._global_var_block, $.var_block),
      repeat($.var_block),
    )),

    _var_blocks: $ => repeat1($.var_block),

    var_block: $ => varBlock($, [...LOCAL_VAR_SECTIONS, ...GLOBAL_VAR_SECTIONS]),
    _local_var_block: $ => varBlock($, LOCAL_VAR_SECTIONS),
    _global_var_block: $ => varBlock($, GLOBAL_VAR_SECTIONS),

    // `a, b AT %IX0.0 : T := init;`, a nameless located variable `AT %IX1.0 : BOOL;`, an
    // edge input `x : BOOL R_EDGE;`, an access path `name : Program.path : T READ_ONLY;`,
    // an instance path in VAR_CONFIG, and matiec's extensible input `IN 1 .. : T`.
    var_declaration: $ => seq(
      choice(
        seq(
          commaSep1(field('name', choice($.identifier, $.qualified_name))),
          optional(seq($.integer, '..', optional($.integer))),
          optional($.location),
        ),
        $.location,
      ),
      ':',
      field('type', $._type),
      optional(seq(':', field('type', $._type))),
      optional(choice(kw('R_EDGE'), kw('F_EDGE'), kw('READ_ONLY'), kw('READ_WRITE'))),
      optional($.initializer),
      ';',
    ),

    location: $ => seq(kw('AT'), $.direct_address),

    // `:= value`, or the 2nd edition's bracketless array initialiser `:= 2, 7, 18`.
    initializer: $ => seq(':=', commaSep1($._initial_value)),

    _initial_value: $ => choice($.struct_initializer, $._expression),

    struct_initializer: $ => seq('(', commaSep1($.field_initializer), ')'),

    field_initializer: $ => seq(field('name', $.identifier), ':=', field('value', $._initial_value)),

    // `[1, 2, 3(0), 4()]`: also an array value in an expression.
    array_initializer: $ => seq(
      '[',
      optional(commaSep1(choice($.repeated_initializer, $._initial_value))),
      ']',
    ),

    // In an array initialiser `3(` repeats, though elsewhere it would call the literal.
    repeated_initializer: $ => prec(PREC.repeat, seq(
      field('count', $.integer),
      '(',
      optional(field('value', $._initial_value)),
      ')',
    )),

    // ---------------------------------------------------------------- configurations

    configuration_declaration: $ => seq(
      kw('CONFIGURATION'),
      field('name', $._declared_name),
      repeat($._configuration_item),
      kw('END_CONFIGURATION'),
    ),

    _configuration_item: $ => choice(
      $.var_block,
      $.resource_declaration,
      $.task_configuration,
      $.program_configuration,
      ';',
    ),

    resource_declaration: $ => seq(
      kw('RESOURCE'),
      field('name', $._declared_name),
      optional(seq(kw('ON'), field('target', $._name_ref))),
      repeat($._configuration_item),
      kw('END_RESOURCE'),
    ),

    task_configuration: $ => seq(
      kw('TASK'),
      field('name', $._declared_name),
      optional($.argument_list),
      ';',
    ),

    program_configuration: $ => seq(
      kw('PROGRAM'),
      optional(kw('RETAIN')),
      field('name', $._declared_name),
      optional(seq(kw('WITH'), field('task', $._name_ref))),
      ':',
      field('type', $._name_ref),
      optional($.argument_list),
      ';',
    ),

    // ---------------------------------------------------------------- statements

    _statement_or_label: $ => choice($._statement, $.label_statement),

    _statement: $ => choice(
      $.assignment_statement,
      $.set_statement,
      $.reset_statement,
      $.reference_assignment_statement,
      $.attempt_assignment_statement,
      $.call_statement,
      $.if_statement,
      $.case_statement,
      $.for_statement,
      $.while_statement,
      $.repeat_statement,
      $.exit_statement,
      $.continue_statement,
      $.return_statement,
      $.jump_statement,
      $.empty_statement,
      $.step,
      $.transition,
    ),

    assignment_statement: $ => seq(
      field('left', $._expression),
      ':=',
      field('right', $._expression),
      ';',
    ),

    // `x S= e;`, `x R= e;` and `p REF= x;`: the word and the `=` are written together.
    set_statement: $ => seq(
      field('left', $._expression),
      alias(token(seq(caseless('S'), '=')), 'S='),
      field('right', $._expression),
      ';',
    ),

    reset_statement: $ => seq(
      field('left', $._expression),
      alias(token(seq(caseless('R'), '=')), 'R='),
      field('right', $._expression),
      ';',
    ),

    reference_assignment_statement: $ => seq(
      field('left', $._expression),
      alias(token(seq(caseless('REF'), '=')), 'REF='),
      field('right', $._expression),
      ';',
    ),

    attempt_assignment_statement: $ => seq(
      field('left', $._expression),
      '?=',
      field('right', $._expression),
      ';',
    ),

    call_statement: $ => seq($.call_expression, ';'),

    if_statement: $ => prec.right(seq(
      kw('IF'),
      field('condition', $._expression),
      kw('THEN'),
      optional($.body),
      repeat($.elsif_clause),
      optional($.else_clause),
      kw('END_IF'),
      optional(';'),
    )),

    elsif_clause: $ => seq(
      kw('ELSIF'),
      field('condition', $._expression),
      kw('THEN'),
      optional($.body),
    ),

    else_clause: $ => seq(kw('ELSE'), optional($.body)),

    case_statement: $ => prec.right(seq(
      kw('CASE'),
      field('selector', $._expression),
      kw('OF'),
      repeat($.case_branch),
      optional($.else_clause),
      kw('END_CASE'),
      optional(';'),
    )),

    // `1, 3..5, E.Idle: statements`. A branch holds no jump labels: `Name:` starts the next
    // branch, as in the compiler.
    case_branch: $ => seq(
      field('label', commaSep1($._case_label)),
      ':',
      optional(alias(repeat1($._statement), $.body)),
    ),

    _case_label: $ => choice($._expression, $.case_range),

    case_range: $ => seq(field('lower', $._expression), '..', field('upper', $._expression)),

    for_statement: $ => prec.right(seq(
      kw('FOR'),
      field('variable', $._expression),
      ':=',
      field('start', $._expression),
      kw('TO'),
      field('end', $._expression),
      optional(seq(kw('BY'), field('step', $._expression))),
      kw('DO'),
      optional($.body),
      kw('END_FOR'),
      optional(';'),
    )),

    while_statement: $ => prec.right(seq(
      kw('WHILE'),
      field('condition', $._expression),
      kw('DO'),
      optional($.body),
      kw('END_WHILE'),
      optional(';'),
    )),

    repeat_statement: $ => prec.right(seq(
      kw('REPEAT'),
      optional($.body),
      kw('UNTIL'),
      field('condition', $._expression),
      kw('END_REPEAT'),
      optional(';'),
    )),

    exit_statement: _ => seq(kw('EXIT'), ';'),

    continue_statement: _ => seq(kw('CONTINUE'), ';'),

    return_statement: _ => seq(kw('RETURN'), ';'),

    jump_statement: $ => seq(kw('JMP'), field('label', $._name_ref), ';'),

    label_statement: $ => seq(field('label', $.identifier), ':'),

    empty_statement: _ => ';',

    // Textual SFC: `INITIAL_STEP Name: actions END_STEP`, with CODESYS's step properties
    // `STEP Name (MIN_TIME := T#1s, ENTRY := In, EXIT := Out): … END_STEP`.
    step: $ => seq(
      choice(
        alias($._initial_step_keyword, 'INITIAL_STEP'),
        alias($._step_keyword, 'STEP'),
      ),
      field('name', $.identifier),
      optional($.step_properties),
      ':',
      optional($.body),
      kw('END_STEP'),
    ),

    // `TRANSITION [Name] [(PRIORITY := n)] FROM a TO (b, c) := condition; END_TRANSITION`.
    transition: $ => seq(
      alias($._transition_keyword, 'TRANSITION'),
      optional(field('name', $.identifier)),
      optional($.argument_list),
      kw('FROM'),
      field('from', $.step_list),
      kw('TO'),
      field('to', $.step_list),
      choice(
        seq(':=', field('condition', $._expression), ';'),
        seq(':', optional($.body)),
      ),
      kw('END_TRANSITION'),
    ),

    step_properties: $ => seq(
      '(',
      commaSep1(seq(
        field('property', choice($.identifier, kw('EXIT'))),
        ':=',
        field('value', $._expression),
      )),
      ')',
    ),

    step_list: $ => choice(
      $._name_ref,
      seq('(', commaSep1($._name_ref), ')'),
    ),

    // ---------------------------------------------------------------- expressions

    _expression: $ => choice(
      $._primary_expression,
      $.unary_expression,
      $.binary_expression,
    ),

    // Operands; member access, indexing, dereference and calls apply to any of them, as in
    // the compiler (the type checker rejects what makes no sense, such as `3.0(x)`).
    _primary_expression: $ => choice(
      $._literal,
      $.typed_literal,
      $.direct_address,
      $.array_initializer,
      $.identifier,
      $.this,
      $.super,
      $.global_reference,
      $.parenthesized_expression,
      $.field_expression,
      $.index_expression,
      $.dereference_expression,
      $.call_expression,
    ),

    parenthesized_expression: $ => seq('(', $._expression, ')'),

    // `.iGlobal`: the global variable, even where a local one hides it.
    global_reference: $ => seq('.', $.identifier),

    field_expression: $ => prec(PREC.postfix, seq(
      field('object', $._primary_expression),
      '.',
      field('field', choice($.identifier, $.integer, $.direct_address)),
    )),

    index_expression: $ => prec(PREC.postfix, seq(
      field('array', $._primary_expression),
      '[',
      commaSep1(field('index', $._expression)),
      ']',
    )),

    dereference_expression: $ => prec(PREC.postfix, seq(
      field('pointer', $._primary_expression),
      '^',
    )),

    // Also the operators called like functions, `MOD(a, b)`, as matiec allows.
    call_expression: $ => prec(PREC.postfix, seq(
      field('function', choice(
        $._primary_expression,
        alias(choice(kw('MOD'), kw('AND'), kw('OR'), kw('XOR')), $.identifier),
      )),
      field('arguments', $.argument_list),
    )),

    argument_list: $ => seq('(', optional(commaSep1($._argument)), ')'),

    _argument: $ => choice($.named_argument, $.output_argument, $._expression),

    named_argument: $ => seq(field('name', $.identifier), ':=', field('value', $._expression)),

    // `Q => x`, `NOT Q => x`, or `Q =>` leaving the output unconnected.
    output_argument: $ => seq(
      optional(kw('NOT')),
      field('name', $.identifier),
      '=>',
      optional(field('target', $._expression)),
    ),

    unary_expression: $ => prec(PREC.unary, seq(
      field('operator', choice(kw('NOT'), '-', '+')),
      field('operand', $._expression),
    )),

    binary_expression: $ => {
      const table = [
        [PREC.or, choice(kw('OR'), kw('OR_ELSE'))],
        [PREC.xor, kw('XOR')],
        [PREC.and, choice(kw('AND'), kw('AND_THEN'), '&')],
        [PREC.equality, choice('=', '<>')],
        [PREC.comparison, choice('<', '<=', '>', '>=')],
        [PREC.additive, choice('+', '-')],
        [PREC.multiplicative, choice('*', '/', kw('MOD'))],
        [PREC.power, '**'],
      ];
      return choice(...table.map(([precedence, operator]) => prec.left(precedence, seq(
        field('left', $._expression),
        field('operator', operator),
        field('right', $._expression),
      ))));
    },

    // `INT#5`, `INT#-5`, `WORD#16#FF`, `E_Color#Red`.
    typed_literal: $ => seq(
      field('type', $.identifier),
      '#',
      optional('-'),
      field('value', choice($._literal, $.identifier)),
    ),

    this: _ => caseless('THIS'),

    super: _ => caseless('SUPER'),

    // ---------------------------------------------------------------- names and tokens

    _declared_name: $ => choice(
      $.identifier,
      // The standard library declares its operator functions under the operators' names.
      alias(choice(kw('MOD'), kw('AND'), kw('OR'), kw('XOR'), kw('NOT')), $.identifier),
    ),

    _name_ref: $ => choice($.identifier, $.qualified_name),

    // `Lib.Type`, `Main.fb.xIn`: the identifiers side by side. A dot after a name always
    // continues it, as in the compiler, though a body could start with `.global`.
    qualified_name: $ => prec(PREC.name, seq($.identifier, '.', $._qualified_name_rest)),
    _qualified_name_rest: $ => choice(
      prec(PREC.name, seq($.identifier, '.', $._qualified_name_rest)),
      $.identifier,
    ),

    _literal: $ => choice(
      $.integer,
      $.real,
      $.time_literal,
      $.date_literal,
      $.string,
      $.wide_string,
      $.boolean,
    ),

    boolean: _ => choice(kw('TRUE'), kw('FALSE')),

    // `42`, `1_000`, `16#FF`, `2#1010_1010`.
    integer: _ => /[0-9][0-9_]*(#[0-9A-Za-z][0-9A-Za-z_]*)?/,

    // `1.5`, `1.5E-3`, `1E6`.
    real: _ => /[0-9][0-9_]*(\.[0-9][0-9_]*([eE][+-]?[0-9]+)?|[eE][+-]?[0-9]+)/,

    // `T#1h2m3s4ms`, `LTIME#5ns`.
    time_literal: _ => token(seq(
      choice(caseless('T'), caseless('TIME'), caseless('LT'), caseless('LTIME')),
      '#',
      /[0-9A-Za-z_.:+\-]*/,
    )),

    // `D#2024-01-31`, `TOD#12:00`, `DT#2024-01-31-12:00`, and their long forms.
    date_literal: _ => token(seq(
      choice(
        caseless('D'),
        caseless('DATE'),
        caseless('LD'),
        caseless('LDATE'),
        caseless('TOD'),
        caseless('TIME_OF_DAY'),
        caseless('LTOD'),
        caseless('LTIME_OF_DAY'),
        caseless('DT'),
        caseless('DATE_AND_TIME'),
        caseless('LDT'),
        caseless('LDATE_AND_TIME'),
      ),
      '#',
      /[0-9A-Za-z_.:+\-]*/,
    )),

    // `'it$'s'`: `$` escapes the next character.
    string: _ => /'([^'$\r\n]|\$[^\r\n])*'/,

    wide_string: _ => /"([^"$\r\n]|\$[^\r\n])*"/,

    // `%IX0.0`, `%QW3`, `%MD10`, `%I*`.
    direct_address: _ => /%[0-9A-Za-z.*]*/,

    // `{attribute 'hide'}`: pragmas are kept in the tree but belong to no rule.
    pragma: _ => /\{[^}]*\}/,

    // Any Unicode letter or digit, so Chinese names work.
    identifier: _ => /[\p{Alphabetic}_][\p{Alphabetic}\p{Nd}\p{Nl}\p{No}_]*/,
  },
});
