//! A read-only, selectable view of source text with line numbers and highlighting.

use egui::text::{LayoutJob, TextFormat};
use egui::{Color32, FontId, TextStyle, Ui};

use crate::{SyntaxColors, TokenClass, classify_tokens};

/// A read-only code view: line numbers in a gutter, Structured Text highlighting, text that can
/// be selected and copied but not changed.
pub struct CodeView<'a> {
    id_salt: egui::IdSalt,
    text: &'a str,
    highlight: bool,
}

impl<'a> CodeView<'a> {
    /// A view of `text`, highlighted as Structured Text. `id_salt` keeps scroll and selection
    /// state apart for views shown side by side.
    pub fn new(id_salt: impl egui::AsIdSalt, text: &'a str) -> Self {
        Self {
            id_salt: egui::IdSalt::new(id_salt),
            text,
            highlight: true,
        }
    }

    /// Shows the text without highlighting (for text that is not Structured Text).
    pub fn plain(mut self) -> Self {
        self.highlight = false;
        self
    }

    /// Draws the view.
    pub fn show(self, ui: &mut Ui) -> egui::Response {
        let font = TextStyle::Monospace.resolve(ui.style());
        let line_count = self.text.lines().count().max(1);
        let digits = line_count.to_string().len();
        let numbers: String = (1..=line_count)
            .map(|line| format!("{line:>digits$}\n"))
            .collect();
        let gutter_color = ui.visuals().weak_text_color();
        let highlight = self.highlight;
        let colors = crate::EditorPalette::of(ui).syntax;
        ui.horizontal_top(|ui| {
            ui.add(
                egui::Label::new(
                    egui::RichText::new(numbers)
                        .font(font.clone())
                        .color(gutter_color),
                )
                .selectable(false),
            );
            let mut layouter = move |ui: &Ui, text: &dyn egui::TextBuffer, wrap_width: f32| {
                let mut job = if highlight {
                    highlighted_job(text.as_str(), &font, &colors, ui.visuals().text_color())
                } else {
                    LayoutJob::simple(
                        text.as_str().to_owned(),
                        font.clone(),
                        ui.visuals().text_color(),
                        f32::INFINITY,
                    )
                };
                job.wrap.max_width = wrap_width.max(f32::INFINITY);
                ui.fonts_mut(|fonts| fonts.layout_job(job))
            };
            let mut text = self.text;
            ui.add(
                egui::TextEdit::multiline(&mut text)
                    .id_salt(self.id_salt)
                    .code_editor()
                    .desired_width(f32::INFINITY)
                    .desired_rows(line_count)
                    .frame(egui::Frame::NONE)
                    .layouter(&mut layouter),
            )
        })
        .inner
    }
}

fn highlighted_job(text: &str, font: &FontId, colors: &SyntaxColors, plain: Color32) -> LayoutJob {
    let mut job = LayoutJob::default();
    for (range, class) in classify_tokens(text) {
        let color = class_color(class, colors).unwrap_or(plain);
        job.append(&text[range], 0.0, TextFormat::simple(font.clone(), color));
    }
    job
}

/// Colours of the token classes; `None` means the theme's text colour.
fn class_color(class: TokenClass, colors: &SyntaxColors) -> Option<Color32> {
    Some(match class {
        TokenClass::Plain => return None,
        TokenClass::Keyword => colors.keyword,
        TokenClass::Comment => colors.comment,
        TokenClass::String => colors.string,
        TokenClass::Number => colors.number,
        TokenClass::Address => colors.label,
        TokenClass::Pragma => colors.attribute,
    })
}
