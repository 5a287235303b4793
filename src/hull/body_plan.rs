//! The body plan of a hull as SVG, drawn the way a naval architect draws it: the sections of the fore
//! body (stations forward of midship) to the right of the centreline, those of the aft body mirrored to
//! the left, midship on both sides; the waterline of each loading, and the sensors marked and named.
//!
//! With trim the waterline differs from station to station: the mean-draft waterline is drawn across,
//! and each section gets a tick at its own local waterline.
//!
//! Every station is labelled (fraction of Lpp aft of the FP) on its own side, midship on the fore side:
//! the labels stand upright in a row above the deck, spread so that no two overlap, each joined by a
//! leader line to the deck end of its section (many sections of a full hull end at the same
//! half-breadth).

use plotters::prelude::*;
use plotters::style::FontTransform;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::Hull;
use super::generate::toml_writer::fmt_decimals;
use crate::error::Result;
use crate::plot::{FONT, draw_error, register_font};

/// Plot-area width in pixels; the height follows from the hull's depth at equal scales.
const PLOT_WIDTH: u32 = 900;
/// Space for the title, axis labels and margins, pixels.
const TOP: u32 = 50;
const BOTTOM: u32 = 55;
const LEFT: u32 = 70;
const MARGIN: u32 = 20;

/// Width of the column of sensor names beside a side that carries sensors, as a fraction of the largest
/// half-breadth.
const CALLOUT_COLUMN: f64 = 0.45;
/// Font size of the sensor names, and the vertical pitch of their column (pixels).
const CALLOUT_FONT: u32 = 15;
const CALLOUT_PX: f64 = 19.0;

/// Station labels: font size; pitch of neighbouring labels (they stand upright, reading upwards);
/// rise of their leader lines above the deck; room kept above the deck for leaders and labels
/// (pixels).
const STATION_FONT: u32 = 14;
const STATION_PITCH_PX: f64 = 15.0;
const STATION_LEADER_PX: f64 = 22.0;
const STATION_BAND_PX: f64 = 66.0;

/// Heights of the names of sensors at heights `z` (sorted upwards): each as close to its sensor as it can
/// be while consecutive names stay at least `gap` apart, kept within (`lo`, `hi`). The same for the
/// station labels along the half-breadth.
fn callout_heights(z: &[f64], gap: f64, lo: f64, hi: f64) -> Vec<f64> {
    let mut out: Vec<f64> = Vec::with_capacity(z.len());
    for &zi in z {
        let below = out.last().map_or(lo + 0.5 * gap, |&l| l + gap);
        out.push(zi.max(below));
    }
    // Pushed over the top: shift down from the top, keeping the gaps.
    let mut ceiling = hi - 0.5 * gap;
    for v in out.iter_mut().rev() {
        if *v > ceiling {
            *v = ceiling;
        }
        ceiling = *v - gap;
    }
    out
}

/// Colours of the loadings' waterlines, in turn.
const WATER: [RGBColor; 3] = [
    RGBColor(0, 90, 200),
    RGBColor(0, 150, 130),
    RGBColor(120, 60, 200),
];

/// Colour of a flat keel.
const FLAT: RGBColor = RGBColor(230, 120, 0);

/// The body plan of `hull` as an SVG document; flat keels drawn thick in orange.
pub fn body_plan_svg(hull: &Hull) -> Result<String> {
    register_font();
    let ymax = hull
        .stations
        .iter()
        .map(|s| s.section.max_half_breadth())
        .fold(0.0, f64::max)
        .max(1e-3);
    let zmin = hull
        .stations
        .iter()
        .map(|s| s.section.keel_z())
        .fold(f64::INFINITY, f64::min)
        .min(0.0);
    let ztop = hull.depth.max(
        hull.stations
            .iter()
            .map(|s| s.section.deck_z())
            .fold(0.0, f64::max),
    );
    let pad = 0.08 * ymax.max(ztop - zmin);
    // A column for the sensor names beside each side that carries sensors (callouts with leader lines,
    // so that names of sensors close together near the keel never overlap).
    let has = |fore: bool| hull.sensors.iter().any(|q| (q.x >= 0.0) == fore);
    let column = |fore: bool| {
        if has(fore) {
            CALLOUT_COLUMN * ymax
        } else {
            0.0
        }
    };
    let (y0, y1) = (-ymax - pad - column(false), ymax + pad + column(true));
    let px_per_m = PLOT_WIDTH as f64 / (y1 - y0);
    // Above the deck: the row of station labels (`z_names` the top of the room left to the rest).
    let z_names = ztop + pad;
    let (z0, z1) = (
        zmin - 0.5 * pad,
        z_names.max(ztop + STATION_BAND_PX / px_per_m),
    );
    let h_plot = (PLOT_WIDTH as f64 * (z1 - z0) / (y1 - y0))
        .round()
        .clamp(150.0, 2000.0) as u32;
    let size = (
        PLOT_WIDTH + LEFT + 2 * MARGIN,
        h_plot + TOP + BOTTOM + 2 * MARGIN,
    );
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE).map_err(draw_error)?;
        let mut chart = ChartBuilder::on(&root)
            .margin(MARGIN)
            .caption(
                format!("{}: body plan (aft body left, fore body right)", hull.name),
                (FONT, 18),
            )
            .x_label_area_size(BOTTOM)
            .y_label_area_size(LEFT)
            .build_cartesian_2d(y0..y1, z0..z1)
            .map_err(draw_error)?;
        chart
            .configure_mesh()
            .x_desc("half-breadth y (m), aft body mirrored to the left; stations labelled by fraction of Lpp aft of the FP")
            .y_desc("z above baseline (m)")
            .x_label_formatter(&|v| fmt_decimals(v.abs(), 4))
            .label_style((FONT, 13))
            .axis_desc_style((FONT, 14))
            .bold_line_style(RGBColor(225, 225, 225))
            .light_line_style(TRANSPARENT)
            .draw()
            .map_err(draw_error)?;
        // Centreline.
        chart
            .draw_series(LineSeries::new(
                [(0.0, z0), (0.0, z1)],
                BLACK.stroke_width(1),
            ))
            .map_err(draw_error)?;
        let mut any_flat = false;
        // Deck end (|y|, z), distance from midship and text of each station's label, per side (aft,
        // fore).
        let mut labels: [Vec<(f64, f64, f64, String)>; 2] = [Vec::new(), Vec::new()];
        for st in &hull.stations {
            let sides: &[f64] = if st.x.abs() < 1e-9 {
                &[-1.0, 1.0]
            } else if st.x > 0.0 {
                &[1.0]
            } else {
                &[-1.0]
            };
            // the assessment's own rule for a flat keel (its air-cushion warning)
            let flat = crate::impact::flat_keel_half_width(&st.section.points);
            let flat_keel = crate::impact::air_cushion_warning(0.0, &st.section.points).is_some();
            any_flat |= flat_keel;
            for &s in sides {
                let pts = st.section.points.iter().map(|p| (s * p[0], p[1]));
                chart
                    .draw_series(LineSeries::new(pts, BLACK.stroke_width(1)))
                    .map_err(draw_error)?;
                if flat_keel {
                    let z = st.section.keel_z();
                    chart
                        .draw_series(LineSeries::new(
                            [(0.0, z), (s * flat, z)],
                            FLAT.stroke_width(4),
                        ))
                        .map_err(draw_error)?;
                }
                for (j, l) in hull.loadings.iter().enumerate() {
                    let zw = l.draft_at(st.x, hull.lpp);
                    let yw = s * st.section.half_breadth_at(zw);
                    let c = WATER[j % WATER.len()];
                    chart
                        .draw_series(std::iter::once(Circle::new((yw, zw), 2, c.filled())))
                        .map_err(draw_error)?;
                }
            }
            let top = st.section.points[st.section.points.len() - 1];
            labels[usize::from(st.x >= 0.0 || st.x.abs() < 1e-9)].push((
                top[0].abs(),
                top[1],
                st.x.abs(),
                format!("{:.3}", hull.aft_of_fp(st.x) + 0.0),
            ));
        }
        // Station labels (fraction of Lpp aft of the FP): upright in a row above the deck, in station
        // order from the end of the ship towards midship, each as close above its deck end as the pitch
        // allows (sections ending at the same half-breadth fan out), with a leader line to the deck end.
        let pitch = STATION_PITCH_PX / px_per_m;
        let z_leader = ztop + STATION_LEADER_PX / px_per_m;
        let z_text = z_leader + 3.0 / px_per_m;
        let style = TextStyle::from((FONT, STATION_FONT).into_font())
            .color(&RGBColor(90, 90, 90))
            .pos(Pos::new(HPos::Left, VPos::Center))
            .transform(FontTransform::Rotate270);
        for (side, mut row) in labels.into_iter().enumerate() {
            let s = if side == 1 { 1.0 } else { -1.0 };
            row.sort_by(|a, b| b.2.total_cmp(&a.2));
            let ys: Vec<f64> = row.iter().map(|l| l.0).collect();
            let hi = if side == 1 { y1 } else { -y0 };
            let at = callout_heights(&ys, pitch, 0.0, hi);
            for ((y, z, _, text), yl) in row.into_iter().zip(at) {
                chart
                    .draw_series(LineSeries::new(
                        [(s * y, z), (s * yl, z_leader)],
                        RGBColor(170, 170, 170).stroke_width(1),
                    ))
                    .map_err(draw_error)?;
                chart
                    .draw_series(std::iter::once(Text::new(
                        text,
                        (s * yl, z_text),
                        style.clone(),
                    )))
                    .map_err(draw_error)?;
            }
        }
        if any_flat {
            let style = TextStyle::from((FONT, 12).into_font())
                .color(&FLAT)
                .pos(Pos::new(HPos::Left, VPos::Bottom));
            chart
                .draw_series(std::iter::once(Text::new(
                    "thick orange: flat keel (bottom impact acoustic, air cushion not modelled)",
                    (y0 + 0.02 * (y1 - y0), z0 + 0.1 * pad),
                    style,
                )))
                .map_err(draw_error)?;
        }
        for (j, l) in hull.loadings.iter().enumerate() {
            let c = WATER[j % WATER.len()];
            let t = l.mean_draft();
            chart
                .draw_series(DashedLineSeries::new(
                    [(y0, t), (y1, t)],
                    6,
                    4,
                    c.stroke_width(1),
                ))
                .map_err(draw_error)?;
            let style = TextStyle::from((FONT, 12).into_font())
                .color(&c)
                .pos(Pos::new(HPos::Left, VPos::Bottom));
            let trim = if l.trim_by_stern().abs() > 0.0 {
                format!(", FP {:.3} m / AP {:.3} m", l.draft_fp, l.draft_ap)
            } else {
                String::new()
            };
            chart
                .draw_series(std::iter::once(Text::new(
                    format!("waterline {}: T = {:.3} m{trim}", l.name, t),
                    (y0 + 0.02 * (y1 - y0), t + 0.1 * pad + j as f64 * 0.6 * pad),
                    style,
                )))
                .map_err(draw_error)?;
        }
        let red = RGBColor(200, 30, 30);
        let leader = RGBColor(215, 140, 140);
        for fore in [true, false] {
            let s = if fore { 1.0 } else { -1.0 };
            let mut marks: Vec<(f64, f64, &str)> = hull
                .sensors
                .iter()
                .filter(|q| (q.x >= 0.0) == fore)
                .map(|q| (s * q.position[0], q.position[1], q.name.as_str()))
                .collect();
            if marks.is_empty() {
                continue;
            }
            marks.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.abs().total_cmp(&b.0.abs())));
            let gap = CALLOUT_PX / px_per_m;
            let z_at = callout_heights(
                &marks.iter().map(|m| m.1).collect::<Vec<_>>(),
                gap,
                z0,
                z_names,
            );
            let y_text = s * (ymax + 0.5 * pad);
            for ((y, z, name), zt) in marks.iter().zip(z_at) {
                chart
                    .draw_series(LineSeries::new(
                        [(*y, *z), (y_text, zt)],
                        leader.stroke_width(1),
                    ))
                    .map_err(draw_error)?;
                chart
                    .draw_series(std::iter::once(Circle::new((*y, *z), 3, red.filled())))
                    .map_err(draw_error)?;
                let style = TextStyle::from((FONT, CALLOUT_FONT).into_font())
                    .color(&red)
                    .pos(Pos::new(
                        if fore { HPos::Left } else { HPos::Right },
                        VPos::Center,
                    ));
                chart
                    .draw_series(std::iter::once(Text::new(
                        format!(" {name}"),
                        (y_text, zt),
                        style,
                    )))
                    .map_err(draw_error)?;
            }
        }
        root.present().map_err(draw_error)?;
    }
    Ok(svg)
}

#[cfg(test)]
mod callout_tests {
    use super::callout_heights;

    #[test]
    fn names_keep_their_gap_and_stay_in_the_plot() {
        let z = [0.0, 0.0, 0.001, 0.1, 0.3];
        let h = callout_heights(&z, 0.02, -0.01, 0.31);
        for w in h.windows(2) {
            assert!(w[1] - w[0] >= 0.02 - 1e-12, "{h:?}");
        }
        assert!(h.iter().all(|&v| v > -0.01 && v < 0.31), "{h:?}");
        // a sensor with room around it keeps its own height
        assert!((h[3] - 0.1).abs() < 1e-12, "{h:?}");
    }
}

#[cfg(test)]
mod station_label_tests {
    use super::{STATION_PITCH_PX, body_plan_svg};
    use crate::hull::Hull;
    use crate::hull::generate::GeneratedHull;

    /// Every station of the bundled hulls has its label (midship once), and no two labels overlap: the
    /// upright labels stand at least the pitch apart (the Ochi hull's 0.174 and 0.227 were left
    /// unlabelled, and its 0.000 and 1.000 printed on top of each other, before).
    #[test]
    fn every_station_is_labelled_and_no_labels_overlap() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("hulls");
        for bundled in GeneratedHull::ALL {
            let name = bundled.file_name();
            let hull = Hull::from_file(&dir.join(name)).unwrap();
            let svg = body_plan_svg(&hull).unwrap();
            // the station labels: the numbers turned upright (the z axis title is upright too)
            let mut labels: Vec<(f64, String)> = svg
                .split("<text ")
                .skip(1)
                .filter(|t| t.contains("rotate(270"))
                .filter_map(|t| {
                    let x = t.split("x=\"").nth(1)?.split('"').next()?;
                    let text = t.split('>').nth(1)?.split('<').next()?.trim();
                    text.parse::<f64>().ok()?;
                    Some((x.parse().unwrap(), text.to_string()))
                })
                .collect();
            let mut want: Vec<String> = hull
                .stations
                .iter()
                .map(|s| format!("{:.3}", hull.aft_of_fp(s.x) + 0.0))
                .collect();
            let mut got: Vec<String> = labels.iter().map(|l| l.1.clone()).collect();
            want.sort();
            got.sort();
            assert_eq!(got, want, "{name}");
            labels.sort_by(|a, b| a.0.total_cmp(&b.0));
            for w in labels.windows(2) {
                assert!(
                    w[1].0 - w[0].0 >= STATION_PITCH_PX - 1.0,
                    "{name}: {} and {} overlap",
                    w[0].1,
                    w[1].1
                );
            }
        }
    }
}
