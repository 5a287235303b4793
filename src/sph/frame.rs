//! PNG snapshots of a run: fluid particles coloured by pressure, the body outline, a colour bar with its
//! unit, the time, and a length scale bar. Text is set in the bundled font (see [`crate::plot`]); the
//! image is PNG-compressed by the `png` crate.

use std::path::Path;

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::error::Result;
use crate::files::write_atomic;
use crate::plot::{FONT, draw_error, encode_png, register_font};
use crate::sph::particles::{Kind, Particles};

/// Height of the strip above the particles for the time label, pixels.
const TOP: u32 = 34;
/// Width of the panel right of the particles for the colour bar, pixels.
const PANEL: u32 = 130;
/// Smallest image height, pixels (room for the colour bar).
const MIN_HEIGHT: u32 = 300;

/// What to draw in one frame.
#[derive(Debug, Clone)]
pub struct Frame {
    /// The window [y0, y1, z0, z1] in m.
    pub window: [f64; 4],
    /// Width of the particle area in pixels (its height follows at equal scales).
    pub width: u32,
    /// Pressure at the top of the colour scale, Pa (0 at the bottom).
    pub p_scale: f64,
    /// Draw each particle also at −y (half-domain runs).
    pub mirror: bool,
    /// Time of the snapshot, s.
    pub time_s: f64,
    /// Body outline (y, z) in m, drawn as a closed line; empty for none.
    pub outline: Vec<[f64; 2]>,
}

/// A blue-cyan-green-yellow-red colour scale over [0, 1] (values outside are clamped for display only).
pub fn colour(x: f64) -> [u8; 3] {
    let x = if x.is_finite() {
        x.clamp(0.0, 1.0)
    } else {
        1.0
    };
    let stops = [
        [0.0, 0.0, 1.0],
        [0.0, 1.0, 1.0],
        [0.0, 1.0, 0.0],
        [1.0, 1.0, 0.0],
        [1.0, 0.0, 0.0],
    ];
    let f = x * 4.0;
    let k = (f.floor() as usize).min(3);
    let t = f - k as f64;
    let mut c = [0u8; 3];
    for m in 0..3 {
        c[m] = ((stops[k][m] * (1.0 - t) + stops[k + 1][m] * t) * 255.0).round() as u8;
    }
    c
}

/// A round length for a scale bar near `target`: 1, 2 or 5 times a power of ten.
pub fn nice_length(target: f64) -> f64 {
    if !(target.is_finite() && target > 0.0) {
        return 1.0;
    }
    let p = 10f64.powf(target.log10().floor());
    [5.0, 2.0, 1.0]
        .into_iter()
        .map(|m| m * p)
        .find(|&l| l <= target)
        .unwrap_or(p)
}

/// A length with its unit (mm below 0.1 m).
fn length_label(l: f64) -> String {
    if l < 0.1 {
        format!("{} mm", trim(l * 1e3))
    } else {
        format!("{} m", trim(l))
    }
}

fn trim(v: f64) -> String {
    let s = format!("{v:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    s.to_string()
}

/// The frame as PNG bytes.
pub fn render_png(pt: &Particles, f: &Frame) -> Result<Vec<u8>> {
    register_font();
    let [y0, y1, z0, z1] = f.window;
    let w = f.width.max(100);
    let h = ((w as f64) * (z1 - z0) / (y1 - y0)).round().max(1.0) as u32;
    let (cw, ch) = (w + PANEL, (h + TOP).max(MIN_HEIGHT));
    let mut img = vec![255u8; (cw * ch * 3) as usize];
    let s = w as f64 / (y1 - y0);
    let to_px = |y: f64, z: f64| ((y - y0) * s, TOP as f64 + (z1 - z) * s);
    // Particles straight into the buffer (faster than drawing elements).
    let dot = 1u32.max((w / 400).min(3));
    let mut plot = |y: f64, z: f64, c: [u8; 3]| {
        let (px, pz) = to_px(y, z);
        if !(px >= 0.0 && pz >= TOP as f64) {
            return;
        }
        let (px, pz) = (px as u32, pz as u32);
        for a in 0..dot {
            for b in 0..dot {
                let (x, yy) = (px + a, pz + b);
                if x < w && yy < (h + TOP).min(ch) {
                    let o = ((yy * cw + x) * 3) as usize;
                    img[o..o + 3].copy_from_slice(&c);
                }
            }
        }
    };
    for i in 0..pt.len() {
        let c = match pt.kind[i] {
            Kind::Fluid => colour(pt.p[i] / f.p_scale),
            Kind::Body => [150, 150, 150],
            Kind::Wall => [64, 64, 64],
            // Air: pale blue-grey, so that the cushion and the escaping air show beside the water.
            Kind::Air => [205, 215, 230],
        };
        plot(pt.y[i], pt.z[i], c);
        if f.mirror {
            plot(-pt.y[i], pt.z[i], c);
        }
    }
    {
        let root = BitMapBackend::with_buffer(&mut img, (cw, ch)).into_drawing_area();
        let ipx = |p: (f64, f64)| (p.0.round() as i32, p.1.round() as i32);
        // Body outline.
        if f.outline.len() >= 2 {
            let pts: Vec<(i32, i32)> = f.outline.iter().map(|p| ipx(to_px(p[0], p[1]))).collect();
            root.draw(&PathElement::new(pts, BLACK.stroke_width(2)))
                .map_err(draw_error)?;
        }
        // Panel background and frame line.
        root.draw(&Rectangle::new(
            [(w as i32, 0), (cw as i32, ch as i32)],
            WHITE.filled(),
        ))
        .map_err(draw_error)?;
        root.draw(&Rectangle::new(
            [(0, 0), (w as i32, TOP as i32)],
            WHITE.filled(),
        ))
        .map_err(draw_error)?;
        // Time.
        let text = |size: u32, h: HPos, v: VPos| {
            TextStyle::from((FONT, size).into_font()).pos(Pos::new(h, v))
        };
        root.draw(&Text::new(
            format!("t = {:.3} ms", f.time_s * 1e3),
            (8, (TOP / 2) as i32),
            text(18, HPos::Left, VPos::Center),
        ))
        .map_err(draw_error)?;
        // Colour bar in kPa, the unit of the reports' tables and plots, whatever the scale.
        let (kilo, unit) = (1e3, "kPa");
        let (bx, bw) = (w as i32 + 20, 22);
        let (btop, bbot) = (TOP as i32 + 30, ch as i32 - 30);
        let span = (bbot - btop).max(1);
        for r in 0..=span {
            let c = colour(1.0 - r as f64 / span as f64);
            root.draw(&Rectangle::new(
                [(bx, btop + r), (bx + bw, btop + r + 1)],
                RGBColor(c[0], c[1], c[2]).filled(),
            ))
            .map_err(draw_error)?;
        }
        root.draw(&Rectangle::new(
            [(bx, btop), (bx + bw, bbot)],
            BLACK.stroke_width(1),
        ))
        .map_err(draw_error)?;
        root.draw(&Text::new(
            format!("p ({unit})"),
            (bx, btop - 10),
            text(15, HPos::Left, VPos::Bottom),
        ))
        .map_err(draw_error)?;
        // Ticks at round values, and the top of the scale (values above it are shown in its colour).
        let top = f.p_scale / kilo;
        let step = nice_length(0.25 * top);
        let mut ticks: Vec<(f64, String)> = (0..)
            .map(|k| k as f64 * step)
            .take_while(|&v| v <= top * (1.0 + 1e-9))
            .filter(|&v| v <= 0.93 * top || v == 0.0)
            .map(|v| (v, fmt_tick(v)))
            .collect();
        ticks.push((top, format!("≥{}", fmt_tick(top))));
        for (v, label) in ticks {
            let y = bbot - (v / top * span as f64).round() as i32;
            root.draw(&PathElement::new(
                vec![(bx + bw, y), (bx + bw + 5, y)],
                BLACK.stroke_width(1),
            ))
            .map_err(draw_error)?;
            root.draw(&Text::new(
                label,
                (bx + bw + 8, y),
                text(13, HPos::Left, VPos::Center),
            ))
            .map_err(draw_error)?;
        }
        // Length scale bar, bottom left of the particle area.
        let len = nice_length(0.25 * (y1 - y0));
        let lpx = (len * s).round() as i32;
        let (sx, sy) = (16, (TOP + h).min(ch) as i32 - 18);
        root.draw(&Rectangle::new(
            [(sx - 2, sy - 24), (sx + lpx + 6, sy + 6)],
            WHITE.filled(),
        ))
        .map_err(draw_error)?;
        root.draw(&Rectangle::new(
            [(sx, sy - 2), (sx + lpx, sy + 2)],
            BLACK.filled(),
        ))
        .map_err(draw_error)?;
        root.draw(&Text::new(
            length_label(len),
            (sx + lpx / 2, sy - 5),
            text(13, HPos::Center, VPos::Bottom),
        ))
        .map_err(draw_error)?;
        root.present().map_err(draw_error)?;
    }
    encode_png(cw, ch, &img)
}

/// A colour-bar tick value with up to three significant decimals.
fn fmt_tick(v: f64) -> String {
    if v >= 100.0 {
        format!("{v:.0}")
    } else if v >= 10.0 {
        trim((v * 10.0).round() / 10.0)
    } else {
        trim((v * 100.0).round() / 100.0)
    }
}

/// Render and write one frame (atomically).
pub fn write_png(path: &Path, pt: &Particles, f: &Frame) -> Result<()> {
    write_atomic(path, &render_png(pt, f)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scale_lengths_are_round() {
        assert_eq!(nice_length(0.3), 0.2);
        assert_eq!(nice_length(0.05), 0.05);
        assert_eq!(nice_length(7.0), 5.0);
        assert_eq!(length_label(0.05), "50 mm");
        assert_eq!(length_label(0.2), "0.2 m");
    }

    #[test]
    fn a_frame_is_a_compressed_png() {
        let mut pt = Particles::default();
        for i in 0..200 {
            let y = 0.001 * i as f64;
            pt.push(
                Kind::Fluid,
                y,
                -0.01,
                0.0,
                0.0,
                1000.0,
                50.0 * i as f64,
                1e-6,
            );
        }
        let f = Frame {
            window: [-0.2, 0.2, -0.1, 0.1],
            width: 400,
            p_scale: 1e4,
            mirror: true,
            time_s: 0.0125,
            outline: vec![[-0.1, 0.05], [0.0, 0.0], [0.1, 0.05]],
        };
        let png = render_png(&pt, &f).unwrap();
        assert_eq!(&png[1..4], b"PNG");
        let (w, h) = (400 + PANEL, 300);
        assert!(png.len() < (w * h * 3 / 10) as usize, "{} bytes", png.len());
    }
}
