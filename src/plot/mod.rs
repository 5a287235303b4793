//! Shared pieces of the pictures the tool draws (body plans, SPH frames): the bundled font and PNG
//! encoding.
//!
//! Text is set in DejaVu Sans, shipped in `assets/fonts/` (licence beside it) and compiled in, so a
//! picture looks the same on every machine. It is registered with plotters' `ab_glyph` text renderer
//! under the family name [`FONT`]; SVG files name that family in their `<text>` elements.

use std::sync::Once;

use plotters::style::FontStyle;

use crate::error::{Error, Result};

/// Family name the bundled font is registered under.
pub const FONT: &str = "DejaVu Sans";

/// The bundled font file (DejaVu Sans, Bitstream Vera licence; see assets/fonts/DejaVuSans-LICENSE.txt).
static FONT_BYTES: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

/// Register the bundled font with plotters (once per process). Must run before any text is drawn.
pub fn register_font() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        // The bytes are a valid TrueType file compiled into the binary; a failure here would be a build
        // problem, and text would then be left out rather than the program stopped.
        let _ = plotters::style::register_font(FONT, FontStyle::Normal, FONT_BYTES);
    });
}

/// Encode 8-bit RGB pixels as a compressed PNG.
pub fn encode_png(width: u32, height: u32, rgb: &[u8]) -> Result<Vec<u8>> {
    let mut out = Vec::new();
    let mut enc = png::Encoder::new(&mut out, width, height);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    enc.set_compression(png::Compression::Balanced);
    let err = |e: png::EncodingError| Error::Invalid(format!("PNG encoding failed: {e}"));
    let mut w = enc.write_header().map_err(err)?;
    w.write_image_data(rgb).map_err(err)?;
    w.finish().map_err(err)?;
    Ok(out)
}

/// A plotters drawing error as a library error.
pub(crate) fn draw_error<E: std::fmt::Debug>(e: E) -> Error {
    Error::Invalid(format!("drawing failed: {e:?}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn png_is_compressed() {
        let rgb = vec![200u8; 300 * 200 * 3];
        let png = encode_png(300, 200, &rgb).unwrap();
        assert_eq!(&png[1..4], b"PNG");
        assert!(png.len() < rgb.len() / 20, "{} bytes", png.len());
    }
}
