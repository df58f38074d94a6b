//! The native blocks, listed once: each with the library name that selects it, the kind of
//! adapter that runs it, and the `motion` function block kept for its instances.

use motion::fb::get_tappet_value::GetTappetValue;
use motion::fb::{
    CamIn, CamOut, CamRegister, CamTableSelect, DigitalCamSwitch, GearIn, GearInPos, GearOut,
    GetCamSlaveSetPosition, Halt, Home, Jog, MoveAbsolute, MoveAdditive, MoveRelative,
    MoveVelocity, Phasing, Power, ReadActualPosition, ReadActualVelocity, ReadAxisError,
    ReadStatus, Reset, SetOverride, SetPosition, Stop,
};

/// Which adapter runs a block.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Adapter {
    /// One `Axis` (`single_axis.rs`).
    SingleAxis,
    /// A master and a slave, a cam or a coupling (`synchronised.rs`).
    Synchronised,
    /// MC_DigitalCamSwitch and its structures (`cam_switch.rs`).
    CamSwitch,
}

/// A `motion` function block kept between calls of its instance.
pub(super) trait Kept: Default {
    /// The block as a kept instance.
    fn wrap(self) -> Instance;
    /// The block, if `instance` holds this type.
    fn unwrap(instance: &mut Instance) -> Option<&mut Self>;
}

macro_rules! native_blocks {
    ($($block:ident $name:literal $adapter:ident),* $(,)?) => {
        /// The native blocks this runtime has, named after the `motion` block behind each.
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        pub(crate) enum NativeBlock {
            $($block,)*
        }

        impl NativeBlock {
            /// The block called `name` (any case) in the motion library.
            pub(super) fn from_name(name: &str) -> Option<Self> {
                $(if name.eq_ignore_ascii_case($name) {
                    return Some(Self::$block);
                })*
                None
            }

            /// The adapter that runs the block.
            pub(super) fn adapter(self) -> Adapter {
                match self {
                    $(Self::$block => Adapter::$adapter,)*
                }
            }
        }

        /// Every kind of kept function block, boxed: the blocks differ much in size (a cam
        /// switch holds its switches and tracks), and the map of instances moves entries.
        pub(super) enum Instance {
            $($block(Box<$block>),)*
        }

        $(
            impl Kept for $block {
                fn wrap(self) -> Instance {
                    Instance::$block(Box::new(self))
                }

                fn unwrap(instance: &mut Instance) -> Option<&mut Self> {
                    match instance {
                        Instance::$block(block) => Some(block),
                        _ => None,
                    }
                }
            }
        )*
    };
}

native_blocks!(
    Power "MC_Power" SingleAxis,
    Home "MC_Home" SingleAxis,
    Stop "MC_Stop" SingleAxis,
    Halt "MC_Halt" SingleAxis,
    Reset "MC_Reset" SingleAxis,
    MoveAbsolute "MC_MoveAbsolute" SingleAxis,
    MoveRelative "MC_MoveRelative" SingleAxis,
    MoveAdditive "MC_MoveAdditive" SingleAxis,
    MoveVelocity "MC_MoveVelocity" SingleAxis,
    Jog "MC_Jog" SingleAxis,
    SetPosition "MC_SetPosition" SingleAxis,
    SetOverride "MC_SetOverride" SingleAxis,
    ReadActualPosition "MC_ReadActualPosition" SingleAxis,
    ReadActualVelocity "MC_ReadActualVelocity" SingleAxis,
    ReadStatus "MC_ReadStatus" SingleAxis,
    ReadAxisError "MC_ReadAxisError" SingleAxis,
    CamTableSelect "MC_CamTableSelect" Synchronised,
    CamIn "MC_CamIn" Synchronised,
    CamOut "MC_CamOut" Synchronised,
    GearIn "MC_GearIn" Synchronised,
    GearOut "MC_GearOut" Synchronised,
    GearInPos "MC_GearInPos" Synchronised,
    Phasing "MC_Phasing" Synchronised,
    CamRegister "SMC_CamRegister" Synchronised,
    GetTappetValue "SMC_GetTappetValue" Synchronised,
    GetCamSlaveSetPosition "SMC_GetCamSlaveSetPosition" Synchronised,
    DigitalCamSwitch "MC_DigitalCamSwitch" CamSwitch,
);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_function_block_of_the_motion_library_has_a_native_block() {
        let library = include_str!("../../../../compiler/src/library/motion.st");
        let blocks: Vec<&str> = library
            .lines()
            .filter_map(|line| line.strip_prefix("FUNCTION_BLOCK "))
            .collect();
        assert_eq!(blocks.len(), 27);
        for name in blocks {
            assert!(NativeBlock::from_name(name.trim()).is_some(), "{name}");
        }
        assert_eq!(NativeBlock::from_name("mc_camin"), Some(NativeBlock::CamIn));
        assert_eq!(NativeBlock::from_name("TON"), None);
    }
}
