//! The standard function blocks (timers, counters, edges, bistables) implemented natively on
//! instances laid out as `program_image::std_blocks` says.

use program_image::StdBlock;
use program_image::std_blocks::{StdLayout, layout};

use super::exec::{ABSOLUTE, Addr, Exec};
use super::fault::FaultKind;
use super::lower::{Flow, Op};

/// Bit 0 of a timer's `_STATE`: the previous `IN`.
const PREVIOUS_IN: u8 = 1;
/// Bit 1 of a timer's `_STATE`: timing.
const RUNNING: u8 = 2;

/// The instruction that runs `block` on an instance.
pub(crate) fn lower(block: StdBlock, long: bool, instance: Addr, indirect: bool) -> Op {
    let shape = layout(block, long);
    let size = shape.size as usize;
    let offsets = Offsets::new(&shape);
    Box::new(move |x| {
        let base = if indirect {
            x.deref(x.get::<u64>(instance)?, size)?
        } else {
            x.at(instance)
        };
        let mut fb = Instance { x, base };
        match block {
            StdBlock::Ton | StdBlock::Tof | StdBlock::Tp => fb.timer(block, long, &offsets)?,
            StdBlock::Ctu | StdBlock::Ctd | StdBlock::Ctud => fb.counter(block, &offsets)?,
            StdBlock::RTrig | StdBlock::FTrig => {
                let clk = fb.bool(offsets.of("CLK"))?;
                let clk = if block == StdBlock::FTrig { !clk } else { clk };
                let memory = fb.bool(offsets.of("_M"))?;
                fb.set_bool(offsets.of("Q"), clk && !memory)?;
                fb.set_bool(offsets.of("_M"), clk)?;
            }
            StdBlock::Sr => {
                let q = fb.bool(offsets.of("S1"))?
                    || (!fb.bool(offsets.of("R"))? && fb.bool(offsets.of("Q1"))?);
                fb.set_bool(offsets.of("Q1"), q)?;
            }
            StdBlock::Rs => {
                let q = !fb.bool(offsets.of("R1"))?
                    && (fb.bool(offsets.of("S"))? || fb.bool(offsets.of("Q1"))?);
                fb.set_bool(offsets.of("Q1"), q)?;
            }
            StdBlock::Rtc => fb.clock(&offsets)?,
        }
        Ok(Flow::Next)
    })
}

/// Member offsets by name, looked up once at load time.
struct Offsets(Vec<(&'static str, u32)>);

impl Offsets {
    fn new(shape: &StdLayout) -> Self {
        Self(shape.members.iter().map(|m| (m.name, m.offset)).collect())
    }

    fn of(&self, name: &str) -> u32 {
        self.0
            .iter()
            .find(|(member, _)| *member == name)
            .map_or(0, |(_, offset)| *offset)
    }
}

struct Instance<'e, 'a> {
    x: &'e mut Exec<'a>,
    base: usize,
}

impl Instance<'_, '_> {
    fn addr(&self, offset: u32) -> Addr {
        Addr {
            base: ABSOLUTE,
            offset: (self.base + offset as usize) as u32,
        }
    }

    fn bool(&self, offset: u32) -> Result<bool, FaultKind> {
        Ok(self.x.get::<u8>(self.addr(offset))? != 0)
    }

    fn set_bool(&mut self, offset: u32, value: bool) -> Result<(), FaultKind> {
        let at = self.addr(offset);
        self.x.set::<u8>(at, u8::from(value))
    }

    fn int(&self, offset: u32) -> Result<i16, FaultKind> {
        self.x.get::<i16>(self.addr(offset))
    }

    fn set_int(&mut self, offset: u32, value: i16) -> Result<(), FaultKind> {
        let at = self.addr(offset);
        self.x.set::<i16>(at, value)
    }

    /// A time member in nanoseconds.
    fn time_ns(&self, offset: u32, long: bool) -> Result<i64, FaultKind> {
        if long {
            self.x.get::<i64>(self.addr(offset))
        } else {
            Ok(i64::from(self.x.get::<i32>(self.addr(offset))?) * 1_000_000)
        }
    }

    fn set_time_ns(&mut self, offset: u32, long: bool, ns: i64) -> Result<(), FaultKind> {
        let at = self.addr(offset);
        if long {
            self.x.set::<i64>(at, ns)
        } else {
            self.x.set::<i32>(at, (ns / 1_000_000) as i32)
        }
    }

    fn timer(&mut self, block: StdBlock, long: bool, o: &Offsets) -> Result<(), FaultKind> {
        let input = self.bool(o.of("IN"))?;
        let preset = self.time_ns(o.of("PT"), long)?;
        let state = self.x.get::<u8>(self.addr(o.of("_STATE")))?;
        let previous = state & PREVIOUS_IN != 0;
        let mut running = state & RUNNING != 0;
        let now = self.x.now_ns;
        let start_at = self.addr(o.of("_START"));
        let mut start = self.x.get::<i64>(start_at)?;
        let elapsed = |start: i64| now.saturating_sub(start).clamp(0, preset.max(0));
        let (q, et) = match block {
            StdBlock::Ton => {
                if !input {
                    running = false;
                    (false, 0)
                } else {
                    if !running {
                        start = now;
                        running = true;
                    }
                    let et = elapsed(start);
                    (et >= preset, et)
                }
            }
            StdBlock::Tof => {
                if input {
                    running = false;
                    (true, 0)
                } else {
                    if previous {
                        start = now;
                        running = true;
                    }
                    if running {
                        let et = elapsed(start);
                        if et >= preset {
                            running = false;
                        }
                        (et < preset, et)
                    } else {
                        let et = self.time_ns(o.of("ET"), long)?;
                        (false, et)
                    }
                }
            }
            _ => {
                // TP: a rising edge starts a pulse of PT that nothing interrupts.
                if input && !previous && !running {
                    start = now;
                    running = true;
                }
                if running {
                    let et = elapsed(start);
                    if et >= preset {
                        running = false;
                    }
                    (et < preset, et)
                } else if input {
                    (false, self.time_ns(o.of("ET"), long)?)
                } else {
                    (false, 0)
                }
            }
        };
        self.set_bool(o.of("Q"), q)?;
        self.set_time_ns(o.of("ET"), long, et)?;
        self.x.set::<i64>(start_at, start)?;
        let state = (u8::from(input) * PREVIOUS_IN) | (u8::from(running) * RUNNING);
        let at = self.addr(o.of("_STATE"));
        self.x.set::<u8>(at, state)
    }

    /// CODESYS's `RTC`: a rising edge of EN sets CDT to PDT and starts counting whole
    /// seconds of the task clock; while EN stays TRUE, Q is TRUE and CDT counts on; EN FALSE
    /// sets Q FALSE and CDT to DT#1970-01-01-00:00:00.
    fn clock(&mut self, o: &Offsets) -> Result<(), FaultKind> {
        let enabled = self.bool(o.of("EN"))?;
        let running = self.bool(o.of("Q"))?;
        let now = self.x.now_ns;
        let start_at = self.addr(o.of("_START"));
        let cdt_at = self.addr(o.of("CDT"));
        if !enabled {
            self.set_bool(o.of("Q"), false)?;
            return self.x.set::<u32>(cdt_at, 0);
        }
        if !running {
            self.x.set::<i64>(start_at, now)?;
            self.set_bool(o.of("Q"), true)?;
        }
        let start = self.x.get::<i64>(start_at)?;
        let preset = self.x.get::<u32>(self.addr(o.of("PDT")))?;
        let seconds = now.saturating_sub(start).max(0) / 1_000_000_000;
        // DT counts seconds in a u32 and wraps in 2106, as CODESYS's does.
        self.x
            .set::<u32>(cdt_at, preset.wrapping_add(seconds as u32))
    }

    fn counter(&mut self, block: StdBlock, o: &Offsets) -> Result<(), FaultKind> {
        let preset = self.int(o.of("PV"))?;
        let mut value = self.int(o.of("CV"))?;
        let edge = |this: &mut Self, input: &str, memory: &str| -> Result<bool, FaultKind> {
            let now = this.bool(o.of(input))?;
            let before = this.bool(o.of(memory))?;
            this.set_bool(o.of(memory), now)?;
            Ok(now && !before)
        };
        match block {
            StdBlock::Ctu => {
                let up = edge(self, "CU", "_M")?;
                if self.bool(o.of("R"))? {
                    value = 0;
                } else if up && value < i16::MAX {
                    value += 1;
                }
                self.set_bool(o.of("Q"), value >= preset)?;
            }
            StdBlock::Ctd => {
                let down = edge(self, "CD", "_M")?;
                if self.bool(o.of("LD"))? {
                    value = preset;
                } else if down && value > i16::MIN {
                    value -= 1;
                }
                self.set_bool(o.of("Q"), value <= 0)?;
            }
            _ => {
                let up = edge(self, "CU", "_MU")?;
                let down = edge(self, "CD", "_MD")?;
                if self.bool(o.of("R"))? {
                    value = 0;
                } else if self.bool(o.of("LD"))? {
                    value = preset;
                } else {
                    if up && value < i16::MAX {
                        value += 1;
                    }
                    if down && value > i16::MIN {
                        value -= 1;
                    }
                }
                self.set_bool(o.of("QU"), value >= preset)?;
                self.set_bool(o.of("QD"), value <= 0)?;
            }
        }
        self.set_int(o.of("CV"), value)
    }
}
