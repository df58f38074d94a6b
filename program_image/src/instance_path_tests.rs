use crate::image::{Region, Symbol, SymbolFlags};
use crate::types::{Member, StructKind, TypeDef};
use crate::{Elementary, ProgramImage};

fn member(name: &str, ty: u32, offset: u32) -> Member {
    Member {
        name: name.to_owned(),
        ty,
        offset,
        located: None,
        flags: 0,
    }
}

/// `Main` at data offset 16: `count : DINT` (0), `fbA : FB_Counter` (4), `aFbs :
/// ARRAY[1..3] OF FB_Counter` (12); `FB_Counter` is `n : DINT` and `inner : FB_Inner` at 4,
/// `FB_Inner` one DINT.
fn image() -> ProgramImage {
    let types = vec![
        TypeDef::Elementary(Elementary::Dint),
        TypeDef::Struct {
            name: "FB_Inner".to_owned(),
            kind: StructKind::FunctionBlock,
            size: 4,
            members: vec![member("v", 0, 0)],
        },
        TypeDef::Struct {
            name: "FB_Counter".to_owned(),
            kind: StructKind::FunctionBlock,
            size: 8,
            members: vec![member("n", 0, 0), member("inner", 1, 4)],
        },
        TypeDef::Array {
            element: 2,
            dims: vec![(1, 3)],
        },
        TypeDef::Struct {
            name: "Main".to_owned(),
            kind: StructKind::Program,
            size: 36,
            members: vec![
                member("count", 0, 0),
                member("fbA", 2, 4),
                member("aFbs", 3, 12),
            ],
        },
    ];
    ProgramImage {
        types,
        symbols: vec![Symbol {
            path: "Main".to_owned(),
            ty: 4,
            region: Region::Data,
            offset: 16,
            bit: None,
            flags: SymbolFlags(0),
        }],
        ..ProgramImage::default()
    }
}

const DATA: u64 = 1 << 56;

#[test]
fn an_instance_is_named_by_its_path_through_members_and_elements() {
    let image = image();
    assert_eq!(
        image.instance_path(DATA | 16, None).as_deref(),
        Some("Main")
    );
    assert_eq!(
        image.instance_path(DATA | 20, None).as_deref(),
        Some("Main.fbA")
    );
    assert_eq!(
        image.instance_path(DATA | (28 + 8), None).as_deref(),
        Some("Main.aFbs[2]")
    );
    assert_eq!(
        image.instance_path(DATA | 24, None).as_deref(),
        Some("Main.fbA.inner")
    );
}

#[test]
fn the_owner_picks_between_instances_at_one_address() {
    let image = image();
    assert_eq!(
        image.instance_path(DATA | 16, Some("Main")).as_deref(),
        Some("Main")
    );
    // `aFbs[1].inner` starts 4 bytes into `aFbs[1]`, which no other instance does.
    assert_eq!(
        image.instance_path(DATA | 32, Some("FB_Inner")).as_deref(),
        Some("Main.aFbs[1].inner")
    );
    assert_eq!(image.instance_path(DATA | 32, Some("FB_Counter")), None);
}

#[test]
fn an_address_of_no_instance_or_of_another_region_has_no_path() {
    let image = image();
    assert_eq!(image.instance_path(DATA | 17, None), None);
    assert_eq!(image.instance_path(DATA | 400, None), None);
    assert_eq!(image.instance_path(2 << 56 | 16, None), None);
    assert_eq!(image.instance_path(0, None), None);
}
