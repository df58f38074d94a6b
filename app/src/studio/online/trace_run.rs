//! A trace's way through the target: resolve its variables, configure and arm it, follow the
//! recording, upload the samples.

use std::collections::HashMap;

use online::{Resolved, Sample, TraceConfig, TraceState, TraceStatus, Trigger};
use project_model::TraceTriggerCondition;

use super::trace_problem::TraceProblem;
use crate::studio::i18n::Language;
use crate::value_text::is_bool;

/// Where a trace is.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TracePhase {
    /// Nothing configured.
    #[default]
    Idle,
    /// Waiting for the target to resolve the variables.
    Resolving,
    /// Configured and armed; waiting for the target to confirm.
    Arming,
    /// Recording on the target.
    Recording {
        /// Samples recorded so far.
        recorded: u32,
        /// Whether the trigger came.
        triggered: bool,
    },
    /// The buffer is full (after the trigger, when there is one).
    Complete,
    /// Samples are being uploaded.
    Uploading {
        /// Samples received.
        received: usize,
        /// Samples in all.
        total: usize,
    },
    /// The samples are here.
    Uploaded,
}

/// One trace run: the configuration asked for and what came back.
#[derive(Clone, Debug, Default)]
pub struct TraceRun {
    phase: TracePhase,
    /// The trace object's name.
    name: String,
    config: Option<project_model::TraceConfig>,
    task_index: u8,
    variables: Vec<(String, Resolved)>,
    samples: Vec<Sample>,
    trigger_sample: Option<u32>,
}

impl TraceRun {
    /// Where the trace is.
    pub fn phase(&self) -> TracePhase {
        self.phase
    }

    /// The trace object this run records.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The recorded variables with their places and types, in configured order.
    pub fn variables(&self) -> &[(String, Resolved)] {
        &self.variables
    }

    /// The uploaded samples.
    pub fn samples(&self) -> &[Sample] {
        &self.samples
    }

    /// The index of the sample at the trigger.
    pub fn trigger_sample(&self) -> Option<u32> {
        self.trigger_sample
    }

    /// Whether the target is recording (statuses are worth asking for).
    pub fn is_recording(&self) -> bool {
        matches!(
            self.phase,
            TracePhase::Arming | TracePhase::Recording { .. }
        )
    }

    /// Starts a run of `config`; returns the paths to resolve. `tasks` are the image's task
    /// names in order.
    pub fn prepare(
        &mut self,
        config: &project_model::TraceConfig,
        tasks: &[String],
        language: Language,
    ) -> Result<Vec<String>, TraceProblem> {
        let task = tasks
            .iter()
            .position(|task| task.eq_ignore_ascii_case(&config.task))
            .ok_or_else(|| TraceProblem::NoSuchTask {
                task: config.task.clone(),
                language,
            })?;
        let task_index = u8::try_from(task).map_err(|_| TraceProblem::TooManyTasks { language })?;
        if config.variables.is_empty() {
            return Err(TraceProblem::NoVariables { language });
        }
        if config.record_count == 0 {
            return Err(TraceProblem::RecordCountZero { language });
        }
        if config.every_n_cycles == 0 || config.every_n_cycles > u32::from(u16::MAX) {
            return Err(TraceProblem::EveryNthOutOfRange {
                every_n_cycles: config.every_n_cycles,
                language,
            });
        }
        let mut paths: Vec<String> = config.variables.iter().map(|v| v.path.clone()).collect();
        if let Some(trigger) = &config.trigger {
            paths.push(trigger.variable.clone());
        }
        *self = Self {
            phase: TracePhase::Resolving,
            name: config.name.clone(),
            config: Some(config.clone()),
            task_index,
            ..Self::default()
        };
        Ok(paths)
    }

    /// The configuration to send, once every path is resolved (once per run). `resolved` holds
    /// the session's answers; a refused path is reported with the session's reason.
    pub fn configuration<ResolveError: std::fmt::Display>(
        &mut self,
        resolved: &HashMap<String, Result<Resolved, ResolveError>>,
        language: Language,
    ) -> Result<Option<TraceConfig>, TraceProblem> {
        if self.phase != TracePhase::Resolving {
            return Ok(None);
        }
        let Some(config) = &self.config else {
            return Ok(None);
        };
        let lookup = |path: &str| -> Result<Option<Resolved>, TraceProblem> {
            match resolved.get(path) {
                None => Ok(None),
                Some(Ok(resolved)) => Ok(Some(*resolved)),
                Some(Err(reason)) => Err(TraceProblem::NotResolved {
                    path: path.to_owned(),
                    reason: reason.to_string(),
                }),
            }
        };
        let mut variables = Vec::new();
        for variable in &config.variables {
            match lookup(&variable.path)? {
                Some(found) => variables.push((variable.path.clone(), found)),
                None => return Ok(None),
            }
        }
        let trigger = match &config.trigger {
            None => Trigger::None,
            Some(trigger) => {
                let Some(found) = lookup(&trigger.variable)? else {
                    return Ok(None);
                };
                if !is_bool(&found) {
                    self.phase = TracePhase::Idle;
                    return Err(TraceProblem::TriggerNotBool {
                        name: trigger.variable.clone(),
                        language,
                    });
                }
                match trigger.condition {
                    TraceTriggerCondition::Rising => Trigger::Rising(found.place),
                    TraceTriggerCondition::Falling => Trigger::Falling(found.place),
                    TraceTriggerCondition::Level => Trigger::Level(found.place),
                }
            }
        };
        let pretrigger_percent = config
            .trigger
            .as_ref()
            .map_or(0, |trigger| trigger.pre_trigger_percent.min(100));
        let every = u16::try_from(config.every_n_cycles).unwrap_or(u16::MAX);
        let out = TraceConfig {
            task: self.task_index,
            every,
            samples: config.record_count,
            pretrigger_percent,
            trigger,
            places: variables
                .iter()
                .map(|(_, resolved)| resolved.place)
                .collect(),
        };
        self.variables = variables;
        Ok(Some(out))
    }

    /// Starts a run recorded by polling a Modbus device: the variables are its channels.
    pub fn device(
        &mut self,
        config: &project_model::TraceConfig,
        variables: Vec<(String, Resolved)>,
    ) {
        *self = Self {
            phase: TracePhase::Recording {
                recorded: 0,
                triggered: false,
            },
            name: config.name.clone(),
            config: Some(config.clone()),
            variables,
            ..Self::default()
        };
    }

    /// The configuration was sent.
    pub fn armed(&mut self) {
        self.phase = TracePhase::Arming;
    }

    /// A command finished on the target.
    pub fn command_done(&mut self) {
        if self.phase == TracePhase::Arming {
            self.phase = TracePhase::Recording {
                recorded: 0,
                triggered: false,
            };
        }
    }

    /// A command failed on the target.
    pub fn command_failed(&mut self) {
        if matches!(
            self.phase,
            TracePhase::Resolving | TracePhase::Arming | TracePhase::Uploading { .. }
        ) {
            self.phase = TracePhase::Idle;
        }
    }

    /// A trace recorded by polling failed: nothing to show.
    pub fn command_failed_always(&mut self) {
        self.phase = TracePhase::Idle;
    }

    /// The target reported the trace's status.
    pub fn status(&mut self, status: TraceStatus) {
        if !self.is_recording() {
            return;
        }
        self.phase = match status.state {
            TraceState::Complete => TracePhase::Complete,
            _ => TracePhase::Recording {
                recorded: status.recorded,
                triggered: status.trigger_sample.is_some() || status.state == TraceState::Triggered,
            },
        };
    }

    /// Starts an upload; `false` when there is nothing configured to upload.
    pub fn begin_upload(&mut self) -> bool {
        if self.variables.is_empty() {
            return false;
        }
        self.phase = TracePhase::Uploading {
            received: 0,
            total: 0,
        };
        true
    }

    /// Upload progress.
    pub fn progress(&mut self, received: usize, total: usize) {
        if matches!(self.phase, TracePhase::Uploading { .. }) {
            self.phase = TracePhase::Uploading { received, total };
        }
    }

    /// The uploaded samples arrived.
    pub fn received(&mut self, samples: Vec<Sample>, trigger_sample: Option<u32>) {
        self.samples = samples;
        self.trigger_sample = trigger_sample;
        self.phase = TracePhase::Uploaded;
    }
}
