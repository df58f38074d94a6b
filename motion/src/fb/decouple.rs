//! The shared body of MC_CamOut and MC_GearOut.

use crate::fb::execute::ExecuteCore;
use crate::kernel::{AxisId, Decoupling, Kernel, MotionError};

/// The shared body of MC_CamOut and MC_GearOut.
#[derive(Clone, Debug, Default)]
pub(crate) struct DecoupleCore {
    core: ExecuteCore,
}

/// The outputs of a decoupling call: `Done`, `Busy`, and the error.
pub(crate) struct DecoupleOutputs {
    pub(crate) done: bool,
    pub(crate) busy: bool,
    pub(crate) error: Option<MotionError>,
}

impl DecoupleCore {
    pub(crate) fn call(
        &mut self,
        execute: bool,
        kernel: &mut Kernel,
        slave: AxisId,
        decoupling: Decoupling,
    ) -> DecoupleOutputs {
        let outputs = self.core.call(execute, kernel, |kernel| {
            kernel.decouple(slave, decoupling).map(|()| None)
        });
        DecoupleOutputs {
            done: outputs.done(),
            busy: outputs.busy,
            error: outputs.error(),
        }
    }
}
