//! The figure of a strength reduction: the mechanism (the magnitude of the
//! displacement since the elastic state at the smallest unstable factor) on
//! the front face of the section, `mechanism.png`.

use std::path::Path;

use plotters::style::RED;

use super::plot::{contour_panels, ContourStyle, Line, Panel, Quantity};
use super::section::{element_mean_displacement, front_patches, water_lines, water_notes};
use crate::drivers::SrmResult;
use crate::error::Error;
use crate::model::Model;

/// Writes `path` (PNG) if the reduction found an unstable factor; returns
/// whether it did.
pub fn mechanism_png(result: &SrmResult, model: &Model, path: &Path) -> Result<bool, Error> {
    let Some(u) = &result.mechanism else { return Ok(false) };
    let magnitude = |e: usize| {
        let c = [0, 1, 2].map(|d| element_mean_displacement(model, u, e, d));
        (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt()
    };
    let patches = front_patches(model, magnitude);
    let title = match (result.fs, result.bracket[1]) {
        (Some(fs), Some(hi)) => format!("strength reduction: FS = {fs:.3}; mechanism at F = {hi:.3}"),
        (_, Some(hi)) => format!("strength reduction: no bracket; mechanism at F = {hi:.3}"),
        _ => "strength reduction".to_string(),
    };
    section_with_water(path, &title, "|u - u_elastic|", Quantity::Displacement, patches, None, model)?;
    Ok(true)
}

/// Writes `path` (PNG): the plastic shear strain (FLAC's measure, the
/// volume average over each element's tetrahedra) at the smallest unstable
/// factor, which marks the slip band through plastic blocks, with the
/// elements that yielded in tension outlined (red: half or more of their
/// tetrahedra on a tension plane at some step, the tension cracks); returns
/// whether there was one to draw.
pub fn slip_band_png(result: &SrmResult, model: &Model, path: &Path) -> Result<bool, Error> {
    let (Some(cells), Some(hi)) = (&result.mechanism_cells, result.bracket[1]) else { return Ok(false) };
    let patches = front_patches(model, |e| cells[e].plastic_shear);
    let cracks: Vec<Line> = patches
        .iter()
        .zip(cells)
        .filter(|(_, c)| c.yielded_tension >= 0.5)
        .map(|(p, _)| Line {
            points: p.corners.iter().chain(p.corners.first()).copied().collect(),
            colour: RED,
            width: 2,
        })
        .collect();
    let overlay = (!cracks.is_empty()).then(|| {
        let note =
            format!("red outline: {} elements yielded in tension (half or more of their tetrahedra)", cracks.len());
        (cracks, note)
    });
    let title = format!("slip band: plastic shear strain at F = {hi:.3}");
    section_with_water(path, &title, "plastic shear strain (-)", Quantity::Plain(""), patches, overlay, model)?;
    Ok(true)
}

/// One section panel with the model's water over it (blue, noted under the
/// panel) and an `overlay`: further lines and the note under the panel that
/// says what they mark.
fn section_with_water(
    path: &Path,
    title: &str,
    label: &str,
    quantity: Quantity,
    patches: Vec<super::plot::Patch>,
    overlay: Option<(Vec<Line>, String)>,
    model: &Model,
) -> Result<(), Error> {
    let (mut lines, mut notes) = (water_lines(model), water_notes(model));
    if let Some((more, note)) = overlay {
        lines.extend(more);
        notes.push(note);
    }
    let panel = Panel { title: String::new(), patches, lines };
    contour_panels(path, title, label, quantity, &[panel], &ContourStyle { notes, ..ContourStyle::default() })
}
