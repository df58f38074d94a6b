//! What the accessors of declarations, types and items return.

use super::tests::{first_in_file, text, token_text};
use super::*;
use crate::syntax::{parse, parse_type};

#[test]
fn a_declaration_has_its_names_address_type_and_initializer() {
    let decl = first_in_file::<VarDecl>("VAR_GLOBAL a, b AT %QW4 : INT := 5; END_VAR");
    let names: Vec<String> = decl.names().map(|n| n.text()).collect();
    assert_eq!(names, ["a", "b"]);
    assert_eq!(
        token_text(decl.address().and_then(|a| a.address())).as_deref(),
        Some("%QW4")
    );
    assert_eq!(text(decl.ty()).as_deref(), Some("INT"));
    assert!(matches!(
        decl.initializer().and_then(|i| i.value()),
        Some(InitValue::Expr(Expr::Literal(_)))
    ));
    let nameless = first_in_file::<VarDecl>("VAR_GLOBAL AT %IX0.0 : BOOL; END_VAR");
    assert_eq!(nameless.name_list(), None);
    assert_eq!(nameless.names().count(), 0);
    let broken = first_in_file::<VarDecl>("VAR_GLOBAL a INT; END_VAR");
    assert_eq!(broken.address(), None);
    assert_eq!(broken.initializer(), None);
}

#[track_caller]
fn type_of(text: &str) -> TypeExpr {
    SourceFile::cast(parse_type(text).syntax())
        .and_then(|file| file.type_expr())
        .unwrap_or_else(|| panic!("no type in {text:?}"))
}

#[test]
fn types_have_their_parts() {
    let TypeExpr::NamedType(named) = type_of("INT(0..100)") else {
        panic!("not a named type");
    };
    assert_eq!(named.name().map(|n| n.text()).as_deref(), Some("INT"));
    let subrange = named.subrange().expect("a subrange");
    assert_eq!(text(subrange.low()).as_deref(), Some("0"));
    assert_eq!(text(subrange.high()).as_deref(), Some("100"));
    let TypeExpr::StringType(string) = type_of("WSTRING[80]") else {
        panic!("not a string type");
    };
    assert_eq!(string.name().map(|n| n.text()).as_deref(), Some("WSTRING"));
    assert_eq!(text(string.length()).as_deref(), Some("80"));
    let TypeExpr::ArrayType(array) = type_of("ARRAY[1..3, *] OF POINTER TO REAL") else {
        panic!("not an array type");
    };
    let ranges: Vec<(Option<String>, Option<String>, bool)> = array
        .ranges()
        .map(|r| (text(r.low()), text(r.high()), r.is_star()))
        .collect();
    assert_eq!(
        ranges,
        [
            (Some("1".into()), Some("3".into()), false),
            (None, None, true)
        ]
    );
    let Some(TypeExpr::PointerType(pointer)) = array.element_type() else {
        panic!("not a pointer element");
    };
    assert_eq!(text(pointer.target()).as_deref(), Some("REAL"));
    let TypeExpr::ReferenceType(reference) = type_of("REF_TO INT") else {
        panic!("not a reference");
    };
    assert!(reference.is_ref_to());
    let TypeExpr::ReferenceType(reference) = type_of("REFERENCE TO INT") else {
        panic!("not a reference");
    };
    assert!(!reference.is_ref_to());
    let TypeExpr::EnumType(enumeration) = type_of("(Idle := 0, Running)") else {
        panic!("not an enumeration");
    };
    let values: Vec<(Option<String>, Option<String>)> = enumeration
        .values()
        .map(|v| (v.name().map(|n| n.text()), text(v.value())))
        .collect();
    assert_eq!(
        values,
        [
            (Some("Idle".into()), Some("0".into())),
            (Some("Running".into()), None)
        ]
    );
    assert_eq!(enumeration.base(), None);
    let based = first_in_file::<EnumType>("TYPE E : (Idle, Running) DINT; END_TYPE");
    assert_eq!(text(based.base()).as_deref(), Some("DINT"));
    let TypeExpr::ArrayType(broken) = type_of("ARRAY[1..] OF") else {
        panic!("not an array type");
    };
    assert_eq!(broken.element_type(), None);
    assert_eq!(broken.ranges().next().and_then(|r| r.high()), None);
}

#[test]
fn initializers_hold_arrays_repetitions_and_structures() {
    let init = first_in_file::<Initializer>(
        "VAR_GLOBAL a : ARRAY[1..5] OF P := [2((x := 1, y := 2)), 3()]; END_VAR",
    );
    let Some(InitValue::Expr(Expr::ArrayInit(array))) = init.value() else {
        panic!("not an array value");
    };
    let elements: Vec<InitValue> = array.elements().collect();
    let [InitValue::Repeat(first), InitValue::Repeat(second)] = elements.as_slice() else {
        panic!("not two repetitions: {elements:?}");
    };
    assert_eq!(first.count(), Some(2));
    assert_eq!(second.count(), Some(3));
    assert_eq!(second.value(), None);
    let Some(InitValue::Struct(structure)) = first.value() else {
        panic!("not a structure value");
    };
    let fields: Vec<(Option<String>, Option<String>)> = structure
        .fields()
        .map(|f| (f.name().map(|n| n.text()), text(f.value())))
        .collect();
    assert_eq!(
        fields,
        [
            (Some("x".into()), Some("1".into())),
            (Some("y".into()), Some("2".into()))
        ]
    );
}

#[test]
fn a_file_lists_its_items_and_a_pou_its_parts() {
    let file = SourceFile::cast(
        parse(
            "FUNCTION_BLOCK FB_A EXTENDS FB_Base IMPLEMENTS I_A, I_B
VAR_INPUT CONSTANT x : INT; END_VAR
VAR RETAIN y : INT; z : BOOL; END_VAR
METHOD Reset : BOOL
VAR_INPUT hard : BOOL; END_VAR
Reset := hard;
END_METHOD
PROPERTY Speed : REAL
GET Speed := 1.0; END_GET
SET ; END_SET
END_PROPERTY
y := x;
END_FUNCTION_BLOCK
TYPE E : (A, B); ST_P : STRUCT a : INT; END_STRUCT; END_TYPE
VAR_GLOBAL g : INT; END_VAR
INTERFACE I_A END_INTERFACE",
        )
        .syntax(),
    )
    .expect("a file is a source file");
    let kinds: Vec<SyntaxKind> = file.items().map(|i| i.syntax().kind()).collect();
    assert_eq!(
        kinds,
        [
            SyntaxKind::POU,
            SyntaxKind::TYPE_DECL,
            SyntaxKind::GLOBAL_VAR_LIST,
            SyntaxKind::INTERFACE_DECL
        ]
    );
    let Some(Item::Pou(pou)) = file.items().next() else {
        panic!("the first item is not a POU");
    };
    assert_eq!(token_text(pou.keyword()).as_deref(), Some("FUNCTION_BLOCK"));
    assert_eq!(pou.name().map(|n| n.text()).as_deref(), Some("FB_A"));
    let names = |clause: Option<Vec<NameRef>>| -> Vec<String> {
        clause.into_iter().flatten().map(|n| n.text()).collect()
    };
    assert_eq!(
        names(pou.extends().map(|c| c.names().collect())),
        ["FB_Base"]
    );
    assert_eq!(
        names(pou.implements().map(|c| c.names().collect())),
        ["I_A", "I_B"]
    );
    let blocks: Vec<VarBlock> = pou.var_blocks().collect();
    assert_eq!(
        token_text(blocks[0].keyword()).as_deref(),
        Some("VAR_INPUT")
    );
    assert!(blocks[0].is_constant());
    assert!(blocks[1].is_retain());
    assert_eq!(blocks[1].declarations().count(), 2);
    let method = pou.methods().next().expect("a method");
    assert_eq!(method.name().map(|n| n.text()).as_deref(), Some("Reset"));
    assert_eq!(text(method.return_type()).as_deref(), Some("BOOL"));
    assert_eq!(text(method.body()).as_deref(), Some("Reset := hard;"));
    let property = pou.properties().next().expect("a property");
    assert_eq!(text(property.ty()).as_deref(), Some("REAL"));
    let gets: Vec<bool> = property.accessors().map(|a| a.is_get()).collect();
    assert_eq!(gets, [true, false]);
    let bodies: Vec<String> = pou.bodies().filter_map(|b| text(Some(b))).collect();
    assert!(bodies.iter().any(|b| b == "y := x;"), "{bodies:?}");
    assert_eq!(pou.return_type(), None);
    let Some(Item::TypeDecl(types)) = file.items().nth(1) else {
        panic!("the second item is not a TYPE");
    };
    let definitions: Vec<TypeDefinition> = types.definitions().collect();
    assert!(matches!(definitions[0].ty(), Some(TypeExpr::EnumType(_))));
    assert_eq!(
        definitions[1].struct_type().map(|s| s.members().count()),
        Some(1)
    );
}

#[test]
fn a_configuration_has_its_resources_tasks_and_programs() {
    let configuration = first_in_file::<ConfigurationDecl>(
        "CONFIGURATION Cell
RESOURCE Cpu ON PLC
TASK Fast(INTERVAL := T#10ms, PRIORITY := 1);
PROGRAM Main WITH Fast : PLC_PRG;
END_RESOURCE
END_CONFIGURATION",
    );
    assert_eq!(
        configuration.name().map(|n| n.text()).as_deref(),
        Some("Cell")
    );
    let resource = configuration.resources().next().expect("a resource");
    assert_eq!(resource.name().map(|n| n.text()).as_deref(), Some("Cpu"));
    assert_eq!(
        resource.processor().map(|n| n.text()).as_deref(),
        Some("PLC")
    );
    let task = resource.tasks().next().expect("a task");
    assert_eq!(task.arg_list().map(|l| l.args().count()), Some(2));
    let program = resource.programs().next().expect("a program");
    assert_eq!(program.name().map(|n| n.text()).as_deref(), Some("Main"));
    assert_eq!(program.task().map(|n| n.text()).as_deref(), Some("Fast"));
    assert_eq!(
        program.program_type().map(|n| n.text()).as_deref(),
        Some("PLC_PRG")
    );
}

#[test]
fn members_keep_their_order_and_modifiers_their_keywords() {
    let pou = first_in_file::<Pou>(
        "FUNCTION_BLOCK ABSTRACT FB_A
VAR PERSISTENT p : INT; END_VAR
VAR RETAIN r : INT; END_VAR
ACTION Act: END_ACTION
METHOD PRIVATE ABSTRACT M : BOOL END_METHOD
PROPERTY PROTECTED P : INT END_PROPERTY
END_FUNCTION_BLOCK",
    );
    assert_eq!(pou.modifiers().collect::<Vec<_>>(), [SyntaxKind::ABSTRACT]);
    let kinds: Vec<SyntaxKind> = pou.members().map(|m| m.syntax().kind()).collect();
    assert_eq!(
        kinds,
        [
            SyntaxKind::ACTION_DECL,
            SyntaxKind::METHOD_DECL,
            SyntaxKind::PROPERTY_DECL
        ]
    );
    let Some(PouMember::MethodDecl(method)) = pou.members().nth(1) else {
        panic!("the second member is not a method");
    };
    assert_eq!(
        method.modifiers().collect::<Vec<_>>(),
        [SyntaxKind::PRIVATE, SyntaxKind::ABSTRACT]
    );
    let Some(PouMember::PropertyDecl(property)) = pou.members().nth(2) else {
        panic!("the third member is not a property");
    };
    assert_eq!(
        property.modifiers().collect::<Vec<_>>(),
        [SyntaxKind::PROTECTED]
    );
    let blocks: Vec<VarBlock> = pou.var_blocks().collect();
    assert!(blocks[0].has_persistent_keyword() && !blocks[0].has_retain_keyword());
    assert!(blocks[0].is_retain());
    assert!(blocks[1].has_retain_keyword() && !blocks[1].has_persistent_keyword());
    let interface = first_in_file::<InterfaceDecl>(
        "INTERFACE I_A PROPERTY P : INT END_PROPERTY METHOD M END_METHOD END_INTERFACE",
    );
    let kinds: Vec<SyntaxKind> = interface.members().map(|m| m.syntax().kind()).collect();
    assert_eq!(kinds, [SyntaxKind::PROPERTY_DECL, SyntaxKind::METHOD_DECL]);
}

#[test]
fn a_declaration_part_holds_variable_sections_as_items() {
    let file = SourceFile::cast(
        crate::syntax::parse_declaration_part("VAR_INPUT a : INT; END_VAR").syntax(),
    )
    .expect("a declaration part is a source file");
    let items: Vec<Item> = file.items().collect();
    assert!(
        matches!(items.as_slice(), [Item::VarBlock(block)] if block.declarations().count() == 1),
        "{items:?}"
    );
}
