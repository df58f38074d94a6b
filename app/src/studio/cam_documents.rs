//! Cam tables open in the studio: one `cam_editor::CamEditor` per cam document, its edits
//! turned into commands (one gesture, one undo step) and its CSV requests fulfilled with file
//! dialogs.

use std::collections::HashMap;
use std::path::Path;

use cam_editor::{CamEditor, CamEditorTexts, CamLive};
use egui::Ui;
use project_model::{CamTable, Edit, Object};

use super::command::{Command, Commands};
use super::i18n::{Language, Text};
use super::status::StatusMessage;
use super::view::StudioView;

/// The editors of the open cams, by cam name, and their words. Kept while the project is open
/// and never saved.
#[derive(Default)]
pub struct CamDocuments {
    editors: HashMap<String, CamEditor>,
    /// The variables the cams drawn while logged in want monitored for their live marker
    /// (`docs/motion.md` §2), taken by the studio when it sets the watched variables.
    live_paths: Vec<String>,
    /// The editors' words and the language they are in.
    texts: Option<(Language, CamEditorTexts)>,
}

impl CamDocuments {
    /// Forgets every editor (another project was opened).
    pub fn clear(&mut self) {
        self.editors.clear();
        self.live_paths.clear();
    }

    /// The variables the cams drawn since the last call want monitored.
    pub fn take_live_paths(&mut self) -> Vec<String> {
        std::mem::take(&mut self.live_paths)
    }

    /// The editors' words in `language`, made again only when the language changes.
    fn texts(&mut self, language: Language) -> CamEditorTexts {
        match &self.texts {
            Some((made_in, texts)) if *made_in == language => texts.clone(),
            _ => {
                let texts = cam_editor_texts(language);
                self.texts = Some((language, texts.clone()));
                texts
            }
        }
    }
}

/// Draws the cam `name` in its editor if it is a cam table; `false` when it is not.
///
/// The cam is read-only while logged in, as the Structured Text editors are.
pub(crate) fn cam_document_ui(
    view: StudioView<'_>,
    cams: &mut CamDocuments,
    commands: &mut Commands,
    ui: &mut Ui,
    name: &str,
) -> bool {
    let Some(project) = view.project() else {
        return false;
    };
    let Some(Object::CamTable(cam)) = project.application.object(name) else {
        return false;
    };
    let language = view.language;
    let read_only = view.online.is_logged_in();
    let texts = cams.texts(language);
    if !cam.comment.is_empty() {
        ui.weak(&cam.comment);
    }
    // Logged in, the cam's MC_CAM_REF shows where the coupling through it is.
    let live = if read_only {
        let paths = live_paths(name);
        let number = |path: &String| {
            view.online
                .value(path)
                .and_then(|value| parse_number(&value.text))
        };
        let values = [number(&paths[0]), number(&paths[1]), number(&paths[2])];
        for path in paths {
            if !cams.live_paths.contains(&path) {
                cams.live_paths.push(path);
            }
        }
        match values {
            [Some(master), Some(slave), bits] => {
                let bits = bits.unwrap_or(0.0) as u32;
                Some(CamLive {
                    master,
                    slave,
                    tappets: cam
                        .tracks
                        .iter()
                        .map(|track| {
                            (1..=32).contains(&track.id) && bits & (1 << (track.id - 1)) != 0
                        })
                        .collect(),
                })
            }
            _ => None,
        }
    } else {
        None
    };
    let editor = cams.editors.entry(name.to_owned()).or_default();
    let output = editor.show(ui, cam, live.as_ref(), &texts, read_only);
    if let Some((label, changed)) = output.edit {
        commands.push(Command::Edit(
            format!("{name}: {label}"),
            vec![Edit::ReplaceObject(Object::CamTable(changed))],
        ));
    }
    // The file dialogs open after the frame, where the studio applies commands.
    if output.import_csv {
        commands.push(Command::ImportCamCsv(name.to_owned()));
    }
    if output.export_csv {
        commands.push(Command::ExportCamCsv(name.to_owned()));
    }
    true
}

/// The members of the cam's `MC_CAM_REF` that the runtime writes for the live marker.
fn live_paths(name: &str) -> [String; 3] {
    ["fMasterPosition", "fSlavePosition", "dwTappets"].map(|member| format!("{name}.{member}"))
}

/// A monitored value's number: an LREAL as text (`67.5`) or a DWORD in IEC hexadecimal
/// (`16#00000003`).
fn parse_number(text: &str) -> Option<f64> {
    match text.split_once('#') {
        Some((radix, digits)) => {
            let radix = radix.parse::<u32>().ok()?;
            u64::from_str_radix(&digits.replace('_', ""), radix)
                .ok()
                .map(|value| value as f64)
        }
        None => text.parse::<f64>().ok(),
    }
}

/// The undo label, the edits and the status message that replace the points of `cam` by those
/// of the CSV file at `path`; a read or parse error is the status message to show, with the
/// file and the line.
pub(crate) fn import_csv_file(
    cam: &CamTable,
    path: &Path,
    language: Language,
) -> Result<(String, Vec<Edit>, StatusMessage), StatusMessage> {
    let result = std::fs::read_to_string(path)
        .map_err(|error| error.to_string())
        .and_then(|text| cam_editor::import_points(cam, &text).map_err(|error| error.to_string()));
    match result {
        Ok(imported) => Ok((
            format!("{}: {}", cam.name, Text::CamImportCsv.get(language)),
            vec![Edit::ReplaceObject(Object::CamTable(imported))],
            StatusMessage::info(format!(
                "{} {}",
                Text::CamImportedFrom.get(language),
                path.display()
            )),
        )),
        Err(error) => Err(StatusMessage::error(format!("{}: {error}", path.display()))),
    }
}

/// Writes the points of `cam` to `path`; returns the outcome for the status bar.
pub(crate) fn export_csv_file(cam: &CamTable, path: &Path, language: Language) -> StatusMessage {
    let result = cam_editor::export_points(cam)
        .map_err(|error| error.to_string())
        .and_then(|text| std::fs::write(path, text).map_err(|error| error.to_string()));
    match result {
        Ok(()) => StatusMessage::info(format!(
            "{} {}",
            Text::CamExportedTo.get(language),
            path.display()
        )),
        Err(error) => StatusMessage::error(format!("{}: {error}", path.display())),
    }
}

/// The cam editor's words in `language`.
fn cam_editor_texts(language: Language) -> CamEditorTexts {
    let get = |text: Text| text.get(language).to_owned();
    CamEditorTexts {
        cam_tab: get(Text::CamTab),
        table_tab: get(Text::CamTableTab),
        tappets_tab: get(Text::Tappets),
        properties_tab: get(Text::CamPropertiesTab),
        import_csv: get(Text::CamImportCsv),
        export_csv: get(Text::CamExportCsv),
        master: get(Text::CamMaster),
        slave: get(Text::CamSlave),
        start: get(Text::CamRangeStart),
        end: get(Text::CamRangeEnd),
        unit: get(Text::CamUnit),
        period: get(Text::CamPeriod),
        smooth_transition: get(Text::CamSmoothTransition),
        slave_period: get(Text::CamSlavePeriod),
        continuity: get(Text::CamContinuity),
        position: get(Text::Position),
        velocity: get(Text::CamVelocity),
        acceleration: get(Text::CamAcceleration),
        jerk: get(Text::CamJerk),
        compile_format: get(Text::CompileFormat),
        format_segments: get(Text::Segments),
        format_xyva: get(Text::CamFormatXyva),
        format_table_1d: get(Text::CamFormatTable1d),
        format_table_2d: get(Text::CamFormatTable2d),
        elements: get(Text::CamElements),
        key_point: get(Text::CamKeyPoint),
        segment: get(Text::CamSegment),
        row: get(Text::CamRow),
        law: get(Text::CamLaw),
        min_position: get(Text::CamMinPosition),
        max_position: get(Text::CamMaxPosition),
        max_velocity: get(Text::CamMaxVelocity),
        max_acceleration: get(Text::CamMaxAcceleration),
        insert_key_point: get(Text::CamInsertKeyPoint),
        delete_key_point: get(Text::CamDeleteKeyPoint),
        interpolation: get(Text::CamInterpolation),
        linear: get(Text::CamLinear),
        cubic: get(Text::CamCubic),
        continuity_warnings: get(Text::CamContinuityWarnings),
        no_continuity_warnings: get(Text::CamNoContinuityWarnings),
        invalid_cam: get(Text::CamInvalid),
        track: get(Text::Track),
        tappet: get(Text::CamTappet),
        add_track: get(Text::CamAddTrack),
        remove_track: get(Text::CamRemoveTrack),
        name: get(Text::CamTrackName),
        hysteresis: get(Text::CamHysteresis),
        dead_time_us: get(Text::CamDeadTime),
        add_tappet: get(Text::CamAddTappet),
        delete_tappet: get(Text::CamDeleteTappet),
        positive_pass: get(Text::PositivePass),
        negative_pass: get(Text::NegativePass),
        no_action: get(Text::NoAction),
        switch_on: get(Text::SwitchOn),
        switch_off: get(Text::SwitchOff),
        invert: get(Text::Invert),
        timed_on: get(Text::OnFor),
        move_key_point: get(Text::CamMoveKeyPoint),
        move_tappet: get(Text::CamMoveTappet),
        not_a_number: get(Text::CamNotANumber),
        start_not_below_end: get(Text::CamStartNotBelowEnd),
        too_few_elements: get(Text::CamTooFewElements),
        not_an_integer: get(Text::CamNotAnInteger),
        lanes_hint: get(Text::CamLanesHint),
        live: get(Text::CamLive),
        live_marker: get(Text::CamLiveMarker),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_english_words_are_the_editors_own_defaults() {
        assert_eq!(
            cam_editor_texts(Language::English),
            CamEditorTexts::default()
        );
    }

    #[test]
    fn every_word_has_a_chinese_translation() {
        let chinese = cam_editor_texts(Language::SimplifiedChinese);
        assert_ne!(chinese.cam_tab, CamEditorTexts::default().cam_tab);
        assert_eq!(chinese.key_point, "关键点");
    }
}
