//! Painting the canvas: the networks in view with their headers, grid dots and, while an
//! element is dragged from the toolbox, the insertion marks.

use egui::{Align2, FontId, Pos2, Rect, Response, Stroke, Ui, vec2};

use super::editor::{DiagramEditor, HEADER_HEIGHT_PX, LEFT_MARGIN_PX, NETWORK_GAP_PX};
use super::paint::PaintContext;
use super::placed::NetworkLayout;
use super::toolbox::{ToolboxBlock, ToolboxItem};
use super::types::DiagramView;
use crate::EditorPalette;

impl DiagramEditor {
    pub(super) fn paint_visible(
        &mut self,
        ui: &Ui,
        origin: Pos2,
        viewport: Rect,
        response: &Response,
    ) {
        let painter = ui.painter_at(ui.clip_rect());
        let palette = EditorPalette::of(ui);
        let visuals = ui.visuals();
        let selected = self.selected_set();
        let context = PaintContext {
            painter: &painter,
            palette,
            line: visuals.text_color(),
            weak: visuals.weak_text_color(),
            zoom: self.zoom,
            cell: self.cell_px(),
            view: self.view,
            selected: &selected,
            diagnostics: &self.marks,
            pin_diagnostics: &self.pin_marks,
            online: self.online.as_ref(),
            placeholder: &self.texts.placeholder,
        };
        let dragged_name = match (
            response.dnd_hover_payload::<ToolboxItem>(),
            response.dnd_hover_payload::<ToolboxBlock>(),
        ) {
            (Some(item), _) => Some(self.item_name(*item).to_owned()),
            (None, Some(block)) => Some(block.0.to_owned()),
            (None, None) => None,
        };
        let dragging = dragged_name.is_some();
        let highlighted = if dragging {
            response
                .hover_pos()
                .and_then(|pointer| self.drop_target(((pointer - origin) / self.zoom).to_pos2()))
        } else {
            None
        };
        let top = viewport.top() / self.zoom;
        let bottom = viewport.bottom() / self.zoom;
        let visible = self.networks_between(top, bottom);
        for index in visible.clone() {
            let block_top = origin + vec2(0.0, self.tops_px[index]) * self.zoom;
            self.paint_header(&painter, index, block_top, &context);
            let network_origin = origin + self.network_origin_px(index).to_vec2() * self.zoom;
            self.paint_grid(&painter, network_origin, index, context.weak);
            context.network(&self.layouts[index], network_origin);
            self.paint_debug_marks(&painter, index, block_top, network_origin);
            if self.layouts[index].elements.is_empty() && self.view == DiagramView::FunctionBlock {
                // An empty FBD network has no rung line to show where it is: a placeholder
                // marks the place to click and insert, as CODESYS shows "???".
                painter.text(
                    network_origin + vec2(8.0, self.cell_px().y / 2.0) * self.zoom,
                    Align2::LEFT_CENTER,
                    &self.texts.placeholder,
                    FontId::monospace(11.0 * self.zoom),
                    context.weak,
                );
            }
            if dragging {
                let mark = highlighted
                    .filter(|(network, _)| *network == index)
                    .and_then(|(_, target)| {
                        self.layouts[index]
                            .insert_points
                            .iter()
                            .find(|point| point.target == target)
                            .map(|point| point.pos)
                    });
                context.insert_points(&self.layouts[index], network_origin, mark);
            }
        }
        self.visible = visible;
        if let (Some(name), Some(pointer)) = (dragged_name, response.hover_pos()) {
            // The dragged item's name follows the pointer, above everything, as a label.
            let layer = egui::LayerId::new(egui::Order::Tooltip, response.id.with("dragged"));
            let ghost = ui.ctx().layer_painter(layer);
            let galley = ghost.layout_no_wrap(name, FontId::proportional(12.0), context.line);
            let text_rect = Rect::from_min_size(pointer + vec2(14.0, 10.0), galley.size());
            ghost.rect_filled(
                text_rect.expand(3.0),
                3.0,
                ui.visuals().widgets.inactive.weak_bg_fill,
            );
            ghost.galley(text_rect.min, galley, context.line);
        }
    }

    /// The debugger's marks of network `index`: in the margin beside its number (its
    /// breakpoint, the halt arrow, a flow bar down its height) and on its elements.
    fn paint_debug_marks(
        &self,
        painter: &egui::Painter,
        index: usize,
        block_top: Pos2,
        network_origin: Pos2,
    ) {
        if self.debug_marks.is_empty() {
            return;
        }
        let zoom = self.zoom;
        let radius = 6.0 * zoom;
        let layout = &self.layouts[index];
        let height = HEADER_HEIGHT_PX + layout.size.y * self.cell_px().y;
        let bar = Rect::from_min_size(
            block_top + vec2(LEFT_MARGIN_PX - 6.0, 0.0) * zoom,
            vec2(3.0, height) * zoom,
        );
        let center = block_top + vec2(LEFT_MARGIN_PX - 16.0, 12.0) * zoom;
        super::super::body_debug_marks::paint_network_marks(
            painter,
            &self.debug_marks,
            index,
            center,
            bar,
            radius,
        );
        for element in &layout.elements {
            let Some(id) = element.id else { continue };
            let rect = Rect::from_min_max(
                network_origin + element.rect.min.to_vec2() * self.cell_px() * zoom,
                network_origin + element.rect.max.to_vec2() * self.cell_px() * zoom,
            );
            super::super::body_debug_marks::paint_element_marks(
                painter,
                &self.debug_marks,
                index,
                id,
                rect,
                radius,
            );
        }
    }

    /// Faint dots where the rows of network `index` meet the columns its elements start and
    /// end at, so the grid lines up with elements sized to their texts.
    fn paint_grid(
        &self,
        painter: &egui::Painter,
        origin: Pos2,
        index: usize,
        color: egui::Color32,
    ) {
        let layout = &self.layouts[index];
        let color = color.gamma_multiply(0.35);
        let radius = 0.8 * self.zoom;
        for column in grid_columns(layout) {
            for row in 0..=layout.size.y as usize {
                let at = origin
                    + vec2(column * self.cell_px().x, row as f32 * self.cell_px().y) * self.zoom;
                painter.circle_filled(at, radius, color);
            }
        }
    }

    fn paint_header(
        &self,
        painter: &egui::Painter,
        index: usize,
        top: Pos2,
        context: &PaintContext<'_>,
    ) {
        let network = &self.networks[index];
        let zoom = self.zoom;
        let selected = self.selection.network == Some(index) && self.selection.elements.is_empty();
        let block_height = (HEADER_HEIGHT_PX
            + self.layouts[index].size.y * self.cell_px().y
            + NETWORK_GAP_PX / 2.0)
            * zoom;
        let block = Rect::from_min_size(
            top,
            vec2(
                (LEFT_MARGIN_PX + self.layouts[index].size.x * self.cell_px().x + 8.0) * zoom,
                block_height,
            ),
        );
        if selected {
            // A light tint of the header and a thin outline, as CODESYS marks a selected
            // network; a fill over the whole drawing would hide its lines and online colours.
            let header = Rect::from_min_size(top, vec2(block.width(), HEADER_HEIGHT_PX * zoom));
            painter.rect_filled(
                header,
                2.0 * zoom,
                context.palette.diagram_selection.gamma_multiply(0.6),
            );
            painter.rect_stroke(
                block,
                2.0 * zoom,
                Stroke::new(1.0, context.palette.power_on),
                egui::StrokeKind::Inside,
            );
        }
        painter.line_segment(
            [block.left_bottom(), block.right_bottom()],
            Stroke::new(0.5, context.weak),
        );
        painter.text(
            top + vec2(6.0, 4.0) * zoom,
            Align2::LEFT_TOP,
            (index + 1).to_string(),
            FontId::proportional(13.0 * zoom),
            context.line,
        );
        let text_left = top + vec2(LEFT_MARGIN_PX, 2.0) * zoom;
        let (title, title_color) = if network.title.is_empty() {
            (
                format!("{} {}", self.texts.network, index + 1),
                context.weak,
            )
        } else {
            (network.title.clone(), context.line)
        };
        painter.text(
            text_left,
            Align2::LEFT_TOP,
            title,
            FontId::proportional(13.0 * zoom),
            title_color,
        );
        // The label, if any, starts the header's second line and the comment follows it.
        let mut second_line = text_left + vec2(0.0, 18.0) * zoom;
        if !network.label.is_empty() {
            let label = painter.text(
                second_line,
                Align2::LEFT_TOP,
                format!("{}:", network.label),
                FontId::monospace(11.0 * zoom),
                context.palette.syntax.label,
            );
            second_line.x = label.right() + 8.0 * zoom;
        }
        if !network.comment.is_empty() {
            painter.text(
                second_line,
                Align2::LEFT_TOP,
                &network.comment,
                FontId::proportional(11.0 * zoom),
                context.palette.syntax.comment,
            );
        }
        if let Some(severity) = self
            .diagnostics
            .iter()
            .filter(|diagnostic| diagnostic.network == index && diagnostic.element.is_none())
            .map(|diagnostic| diagnostic.severity)
            .next()
        {
            let color = match severity {
                crate::Severity::Error => context.palette.error,
                crate::Severity::Warning => context.palette.warning,
                crate::Severity::Info => context.palette.info,
            };
            painter.circle_filled(top + vec2(4.0, 30.0) * zoom, 3.0 * zoom, color);
        }
    }
}

/// The columns (in cells) where `layout`'s elements start or end, each once, left to right: a
/// grid at whole cells would not line up with cells sized to their texts.
pub(super) fn grid_columns(layout: &NetworkLayout) -> Vec<f32> {
    let mut columns: Vec<f32> = layout
        .elements
        .iter()
        .flat_map(|element| [element.rect.min.x, element.rect.max.x])
        .collect();
    columns.sort_by(f32::total_cmp);
    columns.dedup_by(|a, b| (*a - *b).abs() < 0.01);
    columns
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagram::ld_layout;
    use project_model::{ElementId, FlowNode, Network, Operand};

    #[test]
    fn the_grid_columns_are_where_elements_start_and_end() {
        let network = Network {
            rung: vec![
                FlowNode::Operand(Operand {
                    id: ElementId(1),
                    text: "a_rather_long_operand_name".to_owned(),
                    ..Operand::default()
                }),
                FlowNode::Operand(Operand {
                    id: ElementId(2),
                    text: "b".to_owned(),
                    ..Operand::default()
                }),
            ],
            ..Network::default()
        };
        let layout = ld_layout(&network, 0);
        let columns = grid_columns(&layout);
        for element in &layout.elements {
            for x in [element.rect.min.x, element.rect.max.x] {
                assert!(
                    columns.iter().any(|column| (column - x).abs() < 0.01),
                    "{x}"
                );
            }
        }
        // The long operand's cell is wider than one, so its end is not on a whole cell.
        assert!(columns.iter().any(|column| column.fract() > 0.01));
        assert!(columns.windows(2).all(|pair| pair[0] < pair[1]));
    }
}
