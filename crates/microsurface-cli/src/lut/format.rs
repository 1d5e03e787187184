//! The file formats of lookup tables ("LUTs") as real-time engines load them: NumPy `.npy`,
//! 16-bit PNG, OpenEXR, KTX 2.0, and source arrays for C, Rust and WGSL. This module only writes
//! and reads tables; what the numbers mean is the `lut` command's business.
//!
//! # The table
//!
//! A [`LutData`] has `dims`, the node counts per axis, outermost first (e.g. `[roughness, mu]`
//! or `[side, eta, roughness, mu]`), and `values` row-major over the dims with the channels
//! fastest: the value of channel `k` at node `(i0, …, i_{n-1})` is
//! `values[((i0·d1 + i1)·d2 + … + i_{n-1})·c + k]`. Every format keeps exactly this order, so an
//! engine that reads the raw data needs no reshuffling. Tables have 2 to 4 axes and 1 to 4
//! channels; `name`, the axis names and the channel names are identifiers
//! (`[A-Za-z_][A-Za-z0-9_]*`), so that they can name arrays and sit in comments and text
//! attributes unescaped. Values must be finite (no format's source form spells NaN or ∞ the same
//! way, and a LUT holding one is a bug upstream).
//!
//! # The image formats: which axis is which
//!
//! The last axis (μ) is the image's x (width), the second-to-last (roughness) its y (height),
//! row 0 being the first roughness node and the first row of the file (top-left origin, as PNG,
//! EXR and KTX's default orientation `rd` all store it). Why: the split-sum convention of the
//! engines that popularised these tables (UE4's and Filament's DFG LUT: u = cos θ, v =
//! roughness) and a GPU's fastest-varying texture coordinate on the densest axis.
//!
//! PNG and EXR have no depth: the outer axes (tables of 3 or 4 axes) are stacked vertically, the
//! image's height being the product of the outer dims times the roughness count, in row-major
//! order (for `[side, eta, roughness, mu]`, row `y = (side·n_eta + eta)·n_roughness +
//! roughness`): the image's bytes are then the table's bytes. The dims, axis names and channel
//! names travel in a text field so that a reader can undo the stacking (see "Metadata").
//!
//! ## PNG (16-bit)
//! Samples are unsigned 16-bit integers, `round(v·65535)`, so values must lie in [0, 1] (an
//! error otherwise, never a clamp: a clamped LUT is silently wrong); reading returns
//! `q / 65535`, within 0.5/65535 of the value written ([`Format::is_exact`] is false). One
//! channel is stored as grey, three as RGB, four as RGBA; PNG has no two-channel colour type
//! (its grey+alpha would put the second channel in alpha, which loaders premultiply or drop),
//! so two channels are stored as RGB with blue 0. No `gAMA`/`sRGB` chunk is written: load the
//! texture as linear data (`*_UNORM`, never `*_SRGB`). Metadata: a `tEXt` chunk with keyword
//! `microsurface` (and `Software` naming the writer), before the image data.
//!
//! ## OpenEXR
//! 32-bit float samples, one scan-line image (ZIP compression in blocks of 16 lines: lossless,
//! and read by every EXR reader from OpenEXR to tinyexr). The file's channels are named `R`,
//! `G`, `B`, `A` for the table's first, second, third and fourth channel, whatever the table
//! calls them: loaders (tinyexr, OpenImageIO, stb-style `LoadEXR`) fetch R, G, B, A, and a
//! channel called `A` or `B` in the file would land in alpha or blue. The table's own channel
//! names are in the metadata attribute. Metadata: a header attribute `microsurface` of type
//! `string` (and the standard `software` attribute).
//!
//! ## KTX 2.0
//! The Khronos KTX File Format Specification 2.0: uncompressed (`supercompressionScheme` 0),
//! one mip level, little-endian. `vkFormat` is `VK_FORMAT_R32_SFLOAT` (100),
//! `VK_FORMAT_R32G32_SFLOAT` (103) or `VK_FORMAT_R32G32B32A32_SFLOAT` (109): three channels are
//! padded to four with 0, because `R32G32B32_SFLOAT` is rarely sampleable (Vulkan makes no
//! promise for it and Metal and WebGPU lack it). 2 axes make a 2D texture (`pixelWidth` = μ,
//! `pixelHeight` = roughness), 3 a 3D texture (`pixelDepth` = the outer axis), 4 a 3D array
//! texture (`layerCount` = the outermost axis, `pixelDepth` the next). No graphics API has 3D
//! array textures (the spec's section "layerCount" says so and allows them in files): an engine
//! uploads each layer as its own 3D texture, or the whole as a 3D texture of depth
//! `layers·depth`, the data being contiguous in that order (section "levelImages": layers, then
//! z slices, then rows). The Data Format Descriptor (section "Data Format Descriptor") is one
//! basic descriptor block (Khronos Data Format Specification 1.3, section 5) as KTX-Software
//! writes it for these formats: colour model RGBSDA, primaries BT.709, transfer linear, 1×1×1×1
//! texel blocks, `bytesPlane0` the texel's bytes, one 32-bit sample per channel with the
//! float and signed qualifiers and sample bounds −1.0 and 1.0 as f32 bit patterns. Key/value
//! data (section "Key/Value Data"), sorted by key: `KTXwriter` = `microsurface <version>` and
//! `microsurface` = the metadata string, both NUL-terminated.
//!
//! # NumPy `.npy`
//! Format version 1.0 (NumPy Enhancement Proposal 1, "A simple file format for NumPy arrays"):
//! magic `\x93NUMPY`, version `1 0`, a little-endian u16 header length, and the header, a Python
//! dict literal `{'descr': '<f4', 'fortran_order': False, 'shape': (…), }` padded with spaces
//! and a newline so that the data starts at a multiple of 64 bytes (as NumPy's own writer pads;
//! the NEP asks for 16). The shape is `dims + [channels]`, the channel axis dropped for
//! one channel, except where dropping it would be ambiguous: a 1-channel table of 3 or 4 axes
//! whose last has at most 4 nodes keeps a channel axis of length 1. So a reader takes the last
//! axis as channels when the array has 5 axes, or 3 or 4 axes of which the last has at most 4
//! entries. The format stores no names: [`read`] names the table after the file's stem, the axes
//! `axis0`, `axis1`, … and the channels `c0`, `c1`, ….
//!
//! # Source arrays (C, Rust, WGSL)
//! Numbers are printed as the shortest decimal that reads back as the same f32 (Rust's `{:?}`),
//! with an `f` suffix in C and WGSL (a C `float` constant; a WGSL `f32` literal, so that the
//! value never passes through an abstract float). Each file opens with a comment giving the
//! axes, dims, channels and the index math, and a line `microsurface-lut: <metadata>` that
//! [`read`] parses; reading then takes every number with a decimal point or exponent after the
//! declaration's `=` (integers there are array sizes).
//! - C: `static const float name[d0]…[d_{n-1}][c] = {…};` with nested braces (no brace
//!   elision, so `-Wmissing-braces` is quiet), the channel extent dropped for one channel.
//! - Rust: `pub static NAME: [[[f32; c]; d_{n-1}]; …; d0] = […];`, the name in SCREAMING_CASE,
//!   `#[rustfmt::skip]`; the channel extent dropped for one channel. `include!`-able.
//! - WGSL: `const NAME: array<T, N> = array<T, N>(…);`, flat over the nodes, T = `f32`,
//!   `vec2<f32>`, `vec3<f32>` or `vec4<f32>` for 1 to 4 channels (a constant has no
//!   address-space layout, so vec3 needs no padding). Flat because nested WGSL arrays spell
//!   every level's type and an index formula is what a shader writes anyway. `const` rather
//!   than `var<private>`: naga 30 accepts a run-time index into a `const` array and emits it as
//!   one constant table (MSL `constant`, HLSL `static const`), whereas a `var<private>` array is
//!   per invocation, and naga's MSL output copies the whole table into each thread. (A compiler
//!   that rejects the run-time index into a `const` array takes `var<private>` in its place.)
//!
//! # Metadata
//! PNG, EXR, KTX and the source arrays carry one ASCII string,
//! `name=ggx_dfg;axes=sqrt_alpha,mu;dims=32,32;channels=A,B,C`: fields separated by `;`, list
//! items by `,`.

use std::fmt;
use std::fs::File;
use std::io::{BufReader, BufWriter};
use std::path::Path;
use std::str::FromStr;

/// A table as written: `dims` node counts per axis, outermost first (e.g. `[roughness, mu]` or
/// `[side, eta, roughness, mu]`); values row-major over dims, then channels fastest.
#[derive(Clone, Debug, PartialEq)]
pub struct LutData {
    /// An identifier, e.g. `ggx_dfg` (used for array names).
    pub name: String,
    /// One name per dim, e.g. `["sqrt_alpha", "mu"]`.
    pub axes: Vec<String>,
    /// Node counts per axis, outermost first.
    pub dims: Vec<usize>,
    /// Channel names, e.g. `["A", "B", "C"]`; 1 to 4.
    pub channels: Vec<String>,
    /// Row-major over `dims`, channels fastest.
    pub values: Vec<f32>,
}

/// A file format of [`LutData`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// NumPy `.npy` 1.0, `<f4`.
    Npy,
    /// 16-bit PNG, values in [0, 1].
    Png16,
    /// OpenEXR, 32-bit float.
    Exr,
    /// KTX 2.0, 32-bit float.
    Ktx2,
    /// A C `static const float` array.
    C,
    /// A Rust `pub static` array.
    Rust,
    /// A WGSL `const` array.
    Wgsl,
}

impl Format {
    /// Every format, in the order of the command's help.
    pub const ALL: [Format; 7] = [
        Format::Npy,
        Format::Png16,
        Format::Exr,
        Format::Ktx2,
        Format::C,
        Format::Rust,
        Format::Wgsl,
    ];

    /// The name [`FromStr`] takes.
    pub fn name(self) -> &'static str {
        match self {
            Format::Npy => "npy",
            Format::Png16 => "png",
            Format::Exr => "exr",
            Format::Ktx2 => "ktx2",
            Format::C => "c",
            Format::Rust => "rust",
            Format::Wgsl => "wgsl",
        }
    }

    /// The file extension, without the dot (C: `h`, a table being included, not compiled alone).
    pub fn extension(self) -> &'static str {
        match self {
            Format::Npy => "npy",
            Format::Png16 => "png",
            Format::Exr => "exr",
            Format::Ktx2 => "ktx2",
            Format::C => "h",
            Format::Rust => "rs",
            Format::Wgsl => "wgsl",
        }
    }

    /// Whether [`read`] gives back the written f32 values bit for bit (all but 16-bit PNG).
    pub fn is_exact(self) -> bool {
        self != Format::Png16
    }
}

impl fmt::Display for Format {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Format {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        Format::ALL
            .into_iter()
            .find(|f| f.name().eq_ignore_ascii_case(s))
            .ok_or_else(|| {
                let names: Vec<&str> = Format::ALL.iter().map(|f| f.name()).collect();
                format!("unknown LUT format '{s}' (valid: {})", names.join(", "))
            })
    }
}

/// Writes `data` to `path` in `format`; the directory must exist. Errors are one line.
pub fn write(data: &LutData, format: Format, path: &Path) -> Result<(), String> {
    data.check()?;
    match format {
        Format::Npy => write_bytes(path, &npy_bytes(data)?),
        Format::Png16 => write_png(data, path),
        Format::Exr => write_exr(data, path),
        Format::Ktx2 => write_bytes(path, &ktx2_bytes(data)?),
        Format::C | Format::Rust | Format::Wgsl => {
            write_bytes(path, source(data, format).as_bytes())
        }
    }
}

/// Reads what [`write`] wrote: dims, channels and values always; name and axes where the format
/// stores them (see the module docs for the names `.npy` gets). Errors are one line; a truncated
/// or foreign file is an error, never a panic.
pub fn read(format: Format, path: &Path) -> Result<LutData, String> {
    let data = match format {
        Format::Npy => read_npy(&read_bytes(path)?, path),
        Format::Png16 => read_png(path),
        Format::Exr => read_exr(path),
        Format::Ktx2 => read_ktx2(&read_bytes(path)?, path),
        Format::C | Format::Rust | Format::Wgsl => {
            let bytes = read_bytes(path)?;
            let text = std::str::from_utf8(&bytes).map_err(|_| "not UTF-8 text".to_string());
            text.and_then(read_source)
        }
    };
    let data = data.map_err(|e| format!("{}: {e}", path.display()))?;
    data.check()
        .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(data)
}

// ---------------------------------------------------------------------------------------------
// The table's checks and metadata

const MAX_CHANNELS: usize = 4;
/// The metadata's key in PNG (tEXt keyword), EXR (attribute name) and KTX (key/value key).
const META_KEY: &str = "microsurface";
/// The metadata line's tag in the source arrays' comments.
const SOURCE_TAG: &str = "microsurface-lut:";

fn writer_name() -> String {
    format!("microsurface {}", env!("CARGO_PKG_VERSION"))
}

fn is_identifier(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

impl LutData {
    /// Node count (the product of the dims).
    fn nodes(&self) -> usize {
        self.dims.iter().product()
    }

    fn check(&self) -> Result<(), String> {
        if !(2..=4).contains(&self.dims.len()) {
            return Err(format!("a table has 2 to 4 axes, not {}", self.dims.len()));
        }
        if self.dims.contains(&0) {
            return Err(format!("every axis needs a node (dims {:?})", self.dims));
        }
        if self.axes.len() != self.dims.len() {
            return Err(format!(
                "{} axis names for {} dims",
                self.axes.len(),
                self.dims.len()
            ));
        }
        if !(1..=MAX_CHANNELS).contains(&self.channels.len()) {
            return Err(format!(
                "a table has 1 to 4 channels, not {}",
                self.channels.len()
            ));
        }
        let names = std::iter::once(&self.name)
            .chain(&self.axes)
            .chain(&self.channels);
        if let Some(bad) = names.into_iter().find(|s| !is_identifier(s)) {
            return Err(format!(
                "'{bad}' is not an identifier ([A-Za-z_][A-Za-z0-9_]*)"
            ));
        }
        let expected = self
            .dims
            .iter()
            .try_fold(self.channels.len(), |n, &d| n.checked_mul(d))
            .ok_or("the dims overflow")?;
        if self.values.len() != expected {
            return Err(format!(
                "{} values for dims {:?} × {} channels (expected {expected})",
                self.values.len(),
                self.dims,
                self.channels.len()
            ));
        }
        if let Some(i) = self.values.iter().position(|v| !v.is_finite()) {
            return Err(format!(
                "value {i} is {} (tables hold finite values)",
                self.values[i]
            ));
        }
        Ok(())
    }

    fn meta(&self) -> String {
        let dims: Vec<String> = self.dims.iter().map(usize::to_string).collect();
        format!(
            "name={};axes={};dims={};channels={}",
            self.name,
            self.axes.join(","),
            dims.join(","),
            self.channels.join(",")
        )
    }

    /// The image's (width, height): μ across, every outer node's rows stacked down.
    fn image_size(&self) -> Result<(u32, u32), String> {
        let (&width, outer) = self.dims.split_last().expect("checked: 2 to 4 dims");
        let height: usize = outer.iter().product();
        match (u32::try_from(width), u32::try_from(height)) {
            (Ok(w), Ok(h)) => Ok((w, h)),
            _ => Err(format!(
                "dims {:?} exceed an image's 2^32 − 1 pixels a side",
                self.dims
            )),
        }
    }
}

/// The metadata string parsed, values still to be attached.
struct Meta {
    name: String,
    axes: Vec<String>,
    dims: Vec<usize>,
    channels: Vec<String>,
}

impl Meta {
    fn parse(text: &str) -> Result<Meta, String> {
        let (mut name, mut axes, mut dims, mut channels) = (None, None, None, None);
        for field in text.trim().split(';') {
            let (key, value) = field
                .split_once('=')
                .ok_or_else(|| format!("bad metadata field '{field}'"))?;
            let list = || value.split(',').map(str::to_string).collect::<Vec<_>>();
            match key {
                "name" => name = Some(value.to_string()),
                "axes" => axes = Some(list()),
                "channels" => channels = Some(list()),
                "dims" => {
                    let parsed: Result<Vec<usize>, _> = value.split(',').map(str::parse).collect();
                    dims = Some(parsed.map_err(|_| format!("bad dims '{value}' in the metadata"))?);
                }
                _ => {} // later fields: ignored, so that old readers read newer files
            }
        }
        match (name, axes, dims, channels) {
            (Some(name), Some(axes), Some(dims), Some(channels)) => Ok(Meta {
                name,
                axes,
                dims,
                channels,
            }),
            _ => Err(format!(
                "metadata '{text}' lacks name, axes, dims or channels"
            )),
        }
    }

    /// The table with these values ([`read`] checks their count).
    fn with_values(self, values: Vec<f32>) -> LutData {
        LutData {
            name: self.name,
            axes: self.axes,
            dims: self.dims,
            channels: self.channels,
            values,
        }
    }

    fn nodes(&self) -> Result<usize, String> {
        if !(2..=4).contains(&self.dims.len()) || !(1..=MAX_CHANNELS).contains(&self.channels.len())
        {
            return Err(format!(
                "metadata with {} dims and {} channels",
                self.dims.len(),
                self.channels.len()
            ));
        }
        self.dims
            .iter()
            .try_fold(1usize, |n, &d| n.checked_mul(d))
            .ok_or_else(|| "the dims overflow".to_string())
    }
}

fn write_bytes(path: &Path, bytes: &[u8]) -> Result<(), String> {
    std::fs::write(path, bytes).map_err(|e| format!("{}: {e}", path.display()))
}

fn read_bytes(path: &Path) -> Result<Vec<u8>, String> {
    std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))
}

/// The table's name when the file stores none: the file's stem if it is an identifier.
fn name_from_path(path: &Path) -> String {
    let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("");
    if is_identifier(stem) {
        stem.to_string()
    } else {
        "lut".to_string()
    }
}

// ---------------------------------------------------------------------------------------------
// NumPy .npy (NEP 1, format version 1.0)

const NPY_MAGIC: &[u8] = b"\x93NUMPY";
/// NumPy pads the header so that the data starts at a multiple of 64 (aligned loads, mmap).
const NPY_ALIGN: usize = 64;

/// Whether the `.npy` shape has a channel axis (see the module docs for why a 1-channel table
/// sometimes keeps one).
fn npy_has_channel_axis(dims: &[usize], channels: usize) -> bool {
    channels > 1 || (dims.len() >= 3 && dims.last().is_some_and(|&d| d <= MAX_CHANNELS))
}

fn npy_bytes(data: &LutData) -> Result<Vec<u8>, String> {
    let mut shape = data.dims.clone();
    if npy_has_channel_axis(&data.dims, data.channels.len()) {
        shape.push(data.channels.len());
    }
    let shape: Vec<String> = shape.iter().map(usize::to_string).collect();
    let dict = format!(
        "{{'descr': '<f4', 'fortran_order': False, 'shape': ({}), }}",
        shape.join(", ")
    );
    // magic (6) + version (2) + header length (2) + dict + padding + '\n'
    let unpadded = NPY_MAGIC.len() + 4 + dict.len() + 1;
    let header = format!(
        "{dict}{}\n",
        " ".repeat(unpadded.next_multiple_of(NPY_ALIGN) - unpadded)
    );
    let header_len =
        u16::try_from(header.len()).map_err(|_| "the .npy header exceeds 65535 bytes")?;
    let mut bytes = Vec::with_capacity(unpadded + data.values.len() * 4 + NPY_ALIGN);
    bytes.extend_from_slice(NPY_MAGIC);
    bytes.extend_from_slice(&[1, 0]);
    bytes.extend_from_slice(&header_len.to_le_bytes());
    bytes.extend_from_slice(header.as_bytes());
    for v in &data.values {
        bytes.extend_from_slice(&v.to_le_bytes());
    }
    Ok(bytes)
}

/// The value of `'key': value` in the header dict, up to the next top-level comma or brace.
fn npy_field<'a>(header: &'a str, key: &str) -> Result<&'a str, String> {
    let start = header
        .find(&format!("'{key}'"))
        .ok_or_else(|| format!("the .npy header has no '{key}'"))?;
    let rest = header[start + key.len() + 2..].trim_start();
    let rest = rest
        .strip_prefix(':')
        .ok_or_else(|| format!("bad '{key}' in the .npy header"))?
        .trim_start();
    let end = if rest.starts_with('(') {
        rest.find(')').map(|i| i + 1)
    } else {
        rest.find([',', '}'])
    };
    end.map(|i| rest[..i].trim())
        .ok_or_else(|| format!("bad '{key}' in the .npy header"))
}

fn read_npy(bytes: &[u8], path: &Path) -> Result<LutData, String> {
    if bytes.len() < 10 || &bytes[..6] != NPY_MAGIC {
        return Err("not a .npy file (no \\x93NUMPY magic)".into());
    }
    // Versions 2.0 and 3.0 differ only by a u32 header length (3.0: UTF-8 header).
    let (header_len, start) = match bytes[6] {
        1 => (
            usize::from(u16::from_le_bytes([bytes[8], bytes[9]])),
            10usize,
        ),
        2 | 3 if bytes.len() >= 12 => (
            u32::from_le_bytes([bytes[8], bytes[9], bytes[10], bytes[11]]) as usize,
            12,
        ),
        v => return Err(format!("unsupported .npy version {v}.{}", bytes[7])),
    };
    let header = bytes
        .get(start..start.saturating_add(header_len))
        .ok_or("truncated .npy header")?;
    let header = std::str::from_utf8(header)
        .map_err(|_| "the .npy header is not text")?
        .replace('"', "'");
    let descr = npy_field(&header, "descr")?;
    if descr != "'<f4'" {
        return Err(format!(
            "the .npy dtype is {descr}; tables are '<f4' (little-endian f32)"
        ));
    }
    if npy_field(&header, "fortran_order")? != "False" {
        return Err("the .npy array is in Fortran order; tables are in C order".into());
    }
    let shape = npy_field(&header, "shape")?;
    let shape: Result<Vec<usize>, _> = shape
        .trim_start_matches('(')
        .trim_end_matches(')')
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(str::parse)
        .collect();
    let mut dims = shape.map_err(|_| format!("bad .npy shape in '{header}'"))?;
    let channels = match dims.len() {
        2 => 1,
        3 | 4 if dims.last().is_some_and(|&d| d > MAX_CHANNELS) => 1,
        3..=5 => dims.pop().expect("3 to 5 axes"),
        n => return Err(format!("a .npy table has 2 to 5 axes, not {n}")),
    };
    let count = dims
        .iter()
        .try_fold(channels, |n, &d| n.checked_mul(d))
        .and_then(|n| n.checked_mul(4))
        .ok_or("the .npy shape overflows")?;
    let data = &bytes[start + header_len..];
    if data.len() != count {
        return Err(format!(
            "{} data bytes for shape {dims:?} × {channels} (expected {count})",
            data.len()
        ));
    }
    let values = data
        .chunks_exact(4)
        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    Ok(LutData {
        name: name_from_path(path),
        axes: (0..dims.len()).map(|i| format!("axis{i}")).collect(),
        dims,
        channels: (0..channels).map(|i| format!("c{i}")).collect(),
        values,
    })
}

// ---------------------------------------------------------------------------------------------
// 16-bit PNG

fn png_color(channels: usize) -> (png::ColorType, usize) {
    match channels {
        1 => (png::ColorType::Grayscale, 1),
        2 | 3 => (png::ColorType::Rgb, 3), // PNG has no RG: blue is 0
        _ => (png::ColorType::Rgba, 4),
    }
}

fn write_png(data: &LutData, path: &Path) -> Result<(), String> {
    let (width, height) = data.image_size()?;
    let c = data.channels.len();
    let (color, samples) = png_color(c);
    // Quantise before creating the file, so that a bad value leaves no file behind.
    let mut bytes = Vec::with_capacity(data.nodes() * samples * 2);
    for (node, texel) in data.values.chunks_exact(c).enumerate() {
        for k in 0..samples {
            let v = texel.get(k).copied().unwrap_or(0.0);
            if !(0.0..=1.0).contains(&v) {
                return Err(format!(
                    "{}: 16-bit PNG holds values in [0, 1]; channel {} at node {node} is {v}",
                    path.display(),
                    data.channels[k]
                ));
            }
            // In f64, so that v·65535 is exact before rounding.
            let q = (f64::from(v) * 65535.0).round() as u16;
            bytes.extend_from_slice(&q.to_be_bytes());
        }
    }
    let fail = |e: &dyn fmt::Display| format!("{}: {e}", path.display());
    let file = File::create(path).map_err(|e| fail(&e))?;
    let mut encoder = png::Encoder::new(BufWriter::new(file), width, height);
    encoder.set_color(color);
    encoder.set_depth(png::BitDepth::Sixteen);
    encoder
        .add_text_chunk(META_KEY.to_string(), data.meta())
        .map_err(|e| fail(&e))?;
    encoder
        .add_text_chunk("Software".to_string(), writer_name())
        .map_err(|e| fail(&e))?;
    let mut writer = encoder.write_header().map_err(|e| fail(&e))?;
    writer.write_image_data(&bytes).map_err(|e| fail(&e))?;
    writer.finish().map_err(|e| fail(&e))
}

fn read_png(path: &Path) -> Result<LutData, String> {
    let file = File::open(path).map_err(|e| e.to_string())?;
    let mut decoder = png::Decoder::new(BufReader::new(file));
    decoder.set_transformations(png::Transformations::IDENTITY);
    let mut reader = decoder.read_info().map_err(|e| e.to_string())?;
    let info = reader.info();
    let text = info
        .uncompressed_latin1_text
        .iter()
        .find(|t| t.keyword == META_KEY);
    let meta = Meta::parse(
        &text
            .ok_or("no 'microsurface' tEXt chunk: not a table written by microsurface")?
            .text,
    )?;
    let nodes = meta.nodes()?;
    let c = meta.channels.len();
    let (color, samples) = png_color(c);
    let (width, height) = (info.width as usize, info.height as usize);
    let (&mu, outer) = meta.dims.split_last().expect("checked: 2 to 4 dims");
    if info.bit_depth != png::BitDepth::Sixteen || info.color_type != color {
        return Err(format!(
            "{:?} {:?}-bit, not the 16-bit {color:?} of {c} channels",
            info.color_type, info.bit_depth
        ));
    }
    if width != mu || height != outer.iter().product::<usize>() {
        return Err(format!("a {width}×{height} image for dims {:?}", meta.dims));
    }
    let mut buf = vec![
        0;
        reader
            .output_buffer_size()
            .ok_or("the image is too large")?
    ];
    reader.next_frame(&mut buf).map_err(|e| e.to_string())?;
    let mut values = Vec::with_capacity(nodes * c);
    for texel in buf.chunks_exact(2 * samples).take(nodes) {
        for k in 0..c {
            values.push(f32::from(u16::from_be_bytes([texel[2 * k], texel[2 * k + 1]])) / 65535.0);
        }
    }
    Ok(meta.with_values(values))
}

// ---------------------------------------------------------------------------------------------
// OpenEXR

/// The file's channel names: R, G, B, A by position (see the module docs).
const EXR_CHANNELS: [&str; 4] = ["R", "G", "B", "A"];

fn write_exr(data: &LutData, path: &Path) -> Result<(), String> {
    use exr::prelude::*;
    let (width, height) = data.image_size()?;
    let c = data.channels.len();
    let list: SmallVec<[AnyChannel<FlatSamples>; 4]> = (0..c)
        .map(|k| {
            let samples = data.values.iter().skip(k).step_by(c).copied().collect();
            AnyChannel::new(EXR_CHANNELS[k], FlatSamples::F32(samples))
        })
        .collect();
    let meta = AttributeValue::Text(Text::from(data.meta().as_str()));
    let attributes = LayerAttributes {
        software_name: Some(Text::from(writer_name().as_str())),
        other: [(Text::from(META_KEY), meta)].into_iter().collect(),
        ..LayerAttributes::default()
    };
    let size = (width as usize, height as usize);
    let layer = Layer::new(
        size,
        attributes,
        Encoding::SMALL_LOSSLESS,
        AnyChannels::sort(list),
    );
    Image::from_layer(layer)
        .write()
        .to_file(path)
        .map_err(|e| format!("{}: {e}", path.display()))
}

fn read_exr(path: &Path) -> Result<LutData, String> {
    use exr::prelude::*;
    let image = read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .first_valid_layer()
        .all_attributes()
        .non_parallel()
        .from_file(path)
        .map_err(|e| e.to_string())?;
    let layer = &image.layer_data;
    let text = match layer.attributes.other.get(&Text::from(META_KEY)) {
        Some(AttributeValue::Text(text)) => text.to_string(),
        _ => return Err("no 'microsurface' attribute: not a table written by microsurface".into()),
    };
    let meta = Meta::parse(&text)?;
    let nodes = meta.nodes()?;
    let (&mu, outer) = meta.dims.split_last().expect("checked: 2 to 4 dims");
    if layer.size.0 != mu || layer.size.1 != outer.iter().product::<usize>() {
        return Err(format!(
            "a {}×{} image for dims {:?}",
            layer.size.0, layer.size.1, meta.dims
        ));
    }
    let c = meta.channels.len();
    let mut columns = Vec::with_capacity(c);
    for name in &EXR_CHANNELS[..c] {
        let channel = layer.channel_data.list.iter().find(|ch| ch.name == **name);
        match channel.map(|ch| &ch.sample_data) {
            Some(FlatSamples::F32(samples)) if samples.len() == nodes => columns.push(samples),
            Some(_) => return Err(format!("channel {name} is not {nodes} f32 samples")),
            None => return Err(format!("no channel {name}")),
        }
    }
    let values = (0..nodes)
        .flat_map(|i| columns.iter().map(move |col| col[i]))
        .collect();
    Ok(meta.with_values(values))
}

// ---------------------------------------------------------------------------------------------
// KTX 2.0

/// Section "identifier": «KTX 20»\r\n\x1A\n.
const KTX2_IDENTIFIER: [u8; 12] = [
    0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32, 0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A,
];
/// Identifier, 9 header u32s and the index (4 u32s, 2 u64s): section "File Structure".
const KTX2_HEADER_LEN: usize = 80;
/// One level index entry: byteOffset, byteLength, uncompressedByteLength (u64 each).
const KTX2_LEVEL_LEN: usize = 24;
const VK_FORMAT_R32_SFLOAT: u32 = 100;
const VK_FORMAT_R32G32_SFLOAT: u32 = 103;
const VK_FORMAT_R32G32B32A32_SFLOAT: u32 = 109;
/// Khronos Data Format 1.3: colour model, primaries, transfer function, sample qualifiers.
const KHR_DF_MODEL_RGBSDA: u32 = 1;
const KHR_DF_PRIMARIES_BT709: u32 = 1;
const KHR_DF_TRANSFER_LINEAR: u32 = 1;
const KHR_DF_VERSIONNUMBER_1_3: u32 = 2;
const KHR_DF_SAMPLE_DATATYPE_SIGNED: u32 = 0x40;
const KHR_DF_SAMPLE_DATATYPE_FLOAT: u32 = 0x80;
/// Channel ids of the RGBSDA model: red, green, blue, alpha.
const KHR_DF_CHANNEL_RGBSDA: [u32; 4] = [0, 1, 2, 15];
/// The basic descriptor block's fixed part (6 u32s) and one sample (4 u32s).
const KHR_DF_BASIC_LEN: usize = 24;
const KHR_DF_SAMPLE_LEN: usize = 16;

/// The texture's components per texel: 3 channels are padded to 4 (see the module docs).
fn ktx2_components(channels: usize) -> (u32, usize) {
    match channels {
        1 => (VK_FORMAT_R32_SFLOAT, 1),
        2 => (VK_FORMAT_R32G32_SFLOAT, 2),
        _ => (VK_FORMAT_R32G32B32A32_SFLOAT, 4),
    }
}

/// The Data Format Descriptor: dfdTotalSize and one basic block (KTX section "Data Format
/// Descriptor"; Khronos Data Format 1.3 section 5 "Khronos Basic Data Format Descriptor Block").
fn ktx2_dfd(components: usize) -> Vec<u8> {
    let block_size = KHR_DF_BASIC_LEN + KHR_DF_SAMPLE_LEN * components;
    let mut words = vec![
        // dfdTotalSize: this word and the block
        (4 + block_size) as u32,
        // vendorId 0 (Khronos) | descriptorType 0 (basic) << 17
        0,
        // versionNumber (1.3) | descriptorBlockSize << 16
        KHR_DF_VERSIONNUMBER_1_3 | ((block_size as u32) << 16),
        // colorModel | colorPrimaries << 8 | transferFunction << 16 | flags 0 (straight alpha)
        KHR_DF_MODEL_RGBSDA | (KHR_DF_PRIMARIES_BT709 << 8) | (KHR_DF_TRANSFER_LINEAR << 16),
        // texelBlockDimension0..3: 1×1×1×1, each stored minus one
        0,
        // bytesPlane0..3: one plane holding the whole texel
        4 * components as u32,
        // bytesPlane4..7
        0,
    ];
    let qualifiers = KHR_DF_SAMPLE_DATATYPE_FLOAT | KHR_DF_SAMPLE_DATATYPE_SIGNED;
    for (k, channel) in KHR_DF_CHANNEL_RGBSDA.iter().take(components).enumerate() {
        // bitOffset | (bitLength − 1) << 16 | (channelId | qualifiers) << 24
        words.push((32 * k) as u32 | (31 << 16) | ((channel | qualifiers) << 24));
        // samplePosition0..3: the texel's origin
        words.push(0);
        // sampleLower, sampleUpper: −1.0 and 1.0, a signed float format's nominal range
        words.push((-1.0f32).to_bits());
        words.push(1.0f32.to_bits());
    }
    words.iter().flat_map(|w| w.to_le_bytes()).collect()
}

/// Key/value data (section "Key/Value Data"): entries sorted by key, each a u32 byte length, the
/// NUL-terminated key, the NUL-terminated value, padded to 4 bytes.
fn ktx2_kvd(entries: &[(&str, &str)]) -> Vec<u8> {
    let mut sorted = entries.to_vec();
    sorted.sort_by(|a, b| a.0.as_bytes().cmp(b.0.as_bytes()));
    let mut bytes = Vec::new();
    for (key, value) in sorted {
        let len = key.len() + 1 + value.len() + 1;
        bytes.extend_from_slice(&(len as u32).to_le_bytes());
        for s in [key, value] {
            bytes.extend_from_slice(s.as_bytes());
            bytes.push(0);
        }
        bytes.resize(bytes.len().next_multiple_of(4), 0);
    }
    bytes
}

fn ktx2_bytes(data: &LutData) -> Result<Vec<u8>, String> {
    let (vk_format, components) = ktx2_components(data.channels.len());
    let too_big = || format!("dims {:?} exceed KTX's u32 sizes", data.dims);
    let u32_of = |d: usize| u32::try_from(d).map_err(|_| too_big());
    // Width μ, height roughness, then depth and layers (0: absent) for 3 and 4 axes.
    let mut extents = [0u32; 4];
    for (e, &d) in extents.iter_mut().zip(data.dims.iter().rev()) {
        *e = u32_of(d)?;
    }
    let [width, height, depth, layers] = extents;
    let dfd = ktx2_dfd(components);
    let meta = data.meta();
    let writer = writer_name();
    let kvd = ktx2_kvd(&[("KTXwriter", &writer), (META_KEY, &meta)]);
    let dfd_offset = KTX2_HEADER_LEN + KTX2_LEVEL_LEN;
    let kvd_offset = dfd_offset + dfd.len();
    // Section "levelImages": mipPadding aligns the level to lcm(texel block size, 4).
    let texel = 4 * components;
    let level_offset = (kvd_offset + kvd.len()).next_multiple_of(texel);
    let level_len = data.nodes() * texel;
    let mut bytes = Vec::with_capacity(level_offset + level_len);
    bytes.extend_from_slice(&KTX2_IDENTIFIER);
    for word in [vk_format, 4, width, height, depth, layers, 1, 1, 0] {
        // typeSize 4 (f32 components), faceCount 1, levelCount 1, supercompressionScheme 0
        bytes.extend_from_slice(&word.to_le_bytes());
    }
    for word in [dfd_offset, dfd.len(), kvd_offset, kvd.len()] {
        bytes.extend_from_slice(&u32_of(word)?.to_le_bytes());
    }
    bytes.extend_from_slice(&[0; 16]); // sgdByteOffset, sgdByteLength: no global data
    for word in [level_offset, level_len, level_len] {
        bytes.extend_from_slice(&(word as u64).to_le_bytes());
    }
    bytes.extend_from_slice(&dfd);
    bytes.extend_from_slice(&kvd);
    bytes.resize(level_offset, 0);
    for texel in data.values.chunks_exact(data.channels.len()) {
        for k in 0..components {
            bytes.extend_from_slice(&texel.get(k).copied().unwrap_or(0.0).to_le_bytes());
        }
    }
    Ok(bytes)
}

fn le_u32(bytes: &[u8], at: usize) -> Result<u32, String> {
    let b = bytes.get(at..at + 4).ok_or("truncated KTX2 file")?;
    Ok(u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
}

fn le_u64(bytes: &[u8], at: usize) -> Result<usize, String> {
    let b = bytes.get(at..at + 8).ok_or("truncated KTX2 file")?;
    let v = u64::from_le_bytes([b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7]]);
    usize::try_from(v).map_err(|_| "a KTX2 offset beyond memory".to_string())
}

/// The bytes at `offset..offset + len`, or a truncation error.
fn section<'a>(bytes: &'a [u8], offset: usize, len: usize, what: &str) -> Result<&'a [u8], String> {
    offset
        .checked_add(len)
        .and_then(|end| bytes.get(offset..end))
        .ok_or_else(|| format!("the KTX2 {what} lies beyond the file's end"))
}

fn read_ktx2(bytes: &[u8], path: &Path) -> Result<LutData, String> {
    if bytes.len() < KTX2_HEADER_LEN || bytes[..12] != KTX2_IDENTIFIER {
        return Err("not a KTX 2.0 file (no «KTX 20» identifier)".into());
    }
    let word = |i: usize| le_u32(bytes, 12 + 4 * i);
    let (vk_format, type_size) = (word(0)?, word(1)?);
    let [width, height, depth, layers] =
        [word(2)?, word(3)?, word(4)?, word(5)?].map(|w| w as usize);
    let (faces, supercompression) = (word(6)?, word(8)?);
    let components = match vk_format {
        VK_FORMAT_R32_SFLOAT => 1,
        VK_FORMAT_R32G32_SFLOAT => 2,
        VK_FORMAT_R32G32B32A32_SFLOAT => 4,
        f => {
            return Err(format!(
                "vkFormat {f}; tables are R32, R32G32 or R32G32B32A32 SFLOAT"
            ))
        }
    };
    if type_size != 4 || faces != 1 || supercompression != 0 || width == 0 || height == 0 {
        return Err(format!(
            "typeSize {type_size}, faceCount {faces}, supercompression {supercompression}, \
             {width}×{height}: not an uncompressed 2D/3D float table"
        ));
    }
    // DFD: one basic block with one 32-bit float sample per component.
    let dfd = section(
        bytes,
        word(9)? as usize,
        word(10)? as usize,
        "data format descriptor",
    )?;
    let dfd_word = |i: usize| le_u32(dfd, 4 * i);
    let block_size = (dfd_word(2)? >> 16) as usize;
    if dfd_word(0)? as usize != dfd.len()
        || dfd_word(1)? != 0
        || block_size != KHR_DF_BASIC_LEN + KHR_DF_SAMPLE_LEN * components
        || dfd_word(3)? & 0xFF != KHR_DF_MODEL_RGBSDA
    {
        return Err(
            "the data format descriptor is not a basic RGBSDA block for the vkFormat".into(),
        );
    }
    for k in 0..components {
        let sample = dfd_word(7 + 4 * k)?;
        if (sample >> 16) & 0xFF != 31 || (sample >> 24) & KHR_DF_SAMPLE_DATATYPE_FLOAT == 0 {
            return Err(format!(
                "the data format descriptor's sample {k} is not a 32-bit float"
            ));
        }
    }
    let kvd = section(
        bytes,
        word(11)? as usize,
        word(12)? as usize,
        "key/value data",
    )?;
    let mut meta_text = None;
    let mut at = 0;
    while at + 4 <= kvd.len() {
        let len = le_u32(kvd, at)? as usize;
        let entry = section(kvd, at + 4, len, "key/value entry")?;
        if let Some((key, value)) = entry.split_once_nul() {
            if key == META_KEY.as_bytes() {
                let value = value.strip_suffix(&[0]).unwrap_or(value);
                meta_text =
                    Some(std::str::from_utf8(value).map_err(|_| "the metadata is not UTF-8")?);
            }
        }
        at = (at + 4 + len).next_multiple_of(4);
    }
    // Level 0, the base level: its byte length must be exactly the texels of the extents.
    let level = KTX2_HEADER_LEN;
    let (offset, len) = (le_u64(bytes, level)?, le_u64(bytes, level + 8)?);
    let mut dims: Vec<usize> = [layers, depth].into_iter().filter(|&d| d > 0).collect();
    dims.extend([height, width]);
    let texels = dims
        .iter()
        .try_fold(1usize, |n, &d| n.checked_mul(d))
        .ok_or("the extents overflow")?;
    if texels.checked_mul(4 * components) != Some(len) {
        return Err(format!(
            "a level of {len} bytes for extents {dims:?} of {components} floats"
        ));
    }
    let data = section(bytes, offset, len, "level 0")?;
    let meta = match meta_text {
        Some(text) => Meta::parse(text)?,
        None => Meta {
            name: name_from_path(path),
            axes: (0..dims.len()).map(|i| format!("axis{i}")).collect(),
            dims: dims.clone(),
            channels: EXR_CHANNELS[..components]
                .iter()
                .map(|s| s.to_string())
                .collect(),
        },
    };
    let c = meta.channels.len();
    if meta.dims != dims || c > components || (c < components && !(c == 3 && components == 4)) {
        return Err(format!(
            "metadata dims {:?} × {c} for a texture of {dims:?} × {components}",
            meta.dims
        ));
    }
    let values = data
        .chunks_exact(4 * components)
        .flat_map(|t| {
            t.chunks_exact(4)
                .take(c)
                .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        })
        .collect();
    Ok(meta.with_values(values))
}

/// A key/value entry split at its key's NUL.
trait SplitNul {
    fn split_once_nul(&self) -> Option<(&[u8], &[u8])>;
}

impl SplitNul for [u8] {
    fn split_once_nul(&self) -> Option<(&[u8], &[u8])> {
        let i = self.iter().position(|&b| b == 0)?;
        Some((&self[..i], &self[i + 1..]))
    }
}

// ---------------------------------------------------------------------------------------------
// Source arrays: C, Rust, WGSL

/// A number as the shortest decimal that reads back as the same f32, with the language's suffix.
fn number(v: f32, format: Format) -> String {
    match format {
        Format::Rust => format!("{v:?}"),
        _ => format!("{v:?}f"), // C float constant, WGSL f32 literal
    }
}

/// The header comment's lines (without comment markers).
fn header_lines(data: &LutData, format: Format, array: &str) -> Vec<String> {
    let axes: Vec<String> = data
        .axes
        .iter()
        .zip(&data.dims)
        .map(|(a, d)| format!("{a} ({d} nodes)"))
        .collect();
    let c = data.channels.len();
    let index: Vec<String> = data.axes.iter().map(|a| format!("i_{a}")).collect();
    let mut lines = vec![
        format!(
            "{}: a lookup table written by {}.",
            data.name,
            writer_name()
        ),
        format!("Axes, outermost first: {}.", axes.join(", ")),
        format!("Channels: {}.", data.channels.join(", ")),
    ];
    match format {
        Format::Wgsl => {
            // Horner form of the row-major flat index.
            let mut flat = index[0].clone();
            for (i, d) in index.iter().zip(&data.dims).skip(1) {
                flat = format!("({flat}) * {d}u + {i}");
            }
            let element = if c == 1 {
                "the value"
            } else {
                "a vector of the channels in order"
            };
            lines.push(format!(
                "Layout: flat, row-major, the last axis fastest; {array}[{flat}] is {element}."
            ));
        }
        _ => {
            let channel = if c == 1 {
                String::new()
            } else {
                "[channel]".to_string()
            };
            let subscripts: String = index.iter().map(|i| format!("[{i}]")).collect();
            lines.push(format!(
                "Layout: row-major, the last axis fastest; {array}{subscripts}{channel}."
            ));
        }
    }
    lines.push(format!("{SOURCE_TAG} {}", data.meta()));
    lines
}

/// Nested array literal over `extents`, numbers innermost on one line.
fn nested(out: &mut String, values: &[f32], extents: &[usize], format: Format, indent: usize) {
    let (open, close) = if format == Format::Rust {
        ('[', ']')
    } else {
        ('{', '}')
    };
    out.push(open);
    match extents {
        [_] => {
            let numbers: Vec<String> = values.iter().map(|&v| number(v, format)).collect();
            out.push_str(&numbers.join(", "));
        }
        [n, inner @ ..] => {
            let stride = values.len() / n;
            for chunk in values.chunks_exact(stride) {
                out.push('\n');
                out.push_str(&" ".repeat(indent + 4));
                nested(out, chunk, inner, format, indent + 4);
                out.push(',');
            }
            out.push('\n');
            out.push_str(&" ".repeat(indent));
        }
        [] => {}
    }
    out.push(close);
}

fn source(data: &LutData, format: Format) -> String {
    let c = data.channels.len();
    let mut extents = data.dims.clone();
    if c > 1 {
        extents.push(c);
    }
    let upper = data.name.to_ascii_uppercase();
    let mut out = String::new();
    match format {
        Format::C => {
            out.push_str("/*\n");
            for line in header_lines(data, format, &data.name) {
                out.push_str(&format!(" * {line}\n"));
            }
            out.push_str(" */\n");
            let sizes: String = extents.iter().map(|e| format!("[{e}]")).collect();
            out.push_str(&format!("static const float {}{sizes} = ", data.name));
            nested(&mut out, &data.values, &extents, format, 0);
            out.push_str(";\n");
        }
        Format::Rust => {
            for line in header_lines(data, format, &upper) {
                out.push_str(&format!("// {line}\n"));
            }
            let ty = extents
                .iter()
                .rev()
                .fold("f32".to_string(), |ty, e| format!("[{ty}; {e}]"));
            out.push_str(&format!("#[rustfmt::skip]\npub static {upper}: {ty} = "));
            nested(&mut out, &data.values, &extents, format, 0);
            out.push_str(";\n");
        }
        _ => {
            for line in header_lines(data, format, &upper) {
                out.push_str(&format!("// {line}\n"));
            }
            let element = if c == 1 {
                "f32".to_string()
            } else {
                format!("vec{c}<f32>")
            };
            let ty = format!("array<{element}, {}>", data.nodes());
            out.push_str(&format!("const {upper}: {ty} = {ty}(\n"));
            let row = data.dims.last().expect("checked: 2 to 4 dims") * c;
            for (i, line) in data.values.chunks_exact(row).enumerate() {
                let items: Vec<String> = line
                    .chunks_exact(c)
                    .map(|t| {
                        let n: Vec<String> = t.iter().map(|&v| number(v, format)).collect();
                        if c == 1 {
                            n.join("")
                        } else {
                            format!("{element}({})", n.join(", "))
                        }
                    })
                    .collect();
                let comma = if (i + 1) * row < data.values.len() {
                    ","
                } else {
                    ""
                };
                out.push_str(&format!("    {}{comma}\n", items.join(", ")));
            }
            out.push_str(");\n");
        }
    }
    out
}

/// Every number token with a decimal point or exponent, in order (identifiers such as `f32` or
/// `vec3` and integers such as array sizes are skipped; a trailing `f` is an identifier).
fn float_tokens(text: &str) -> Result<Vec<f32>, String> {
    let bytes = text.as_bytes();
    let mut values = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let b = bytes[i];
        let starts_number = |j: usize| {
            bytes
                .get(j)
                .is_some_and(|b| b.is_ascii_digit() || *b == b'.')
        };
        if b.is_ascii_alphabetic() || b == b'_' {
            while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                i += 1;
            }
        } else if starts_number(i) || (b == b'-' && starts_number(i + 1)) {
            let start = i;
            i += 1;
            while i < bytes.len() {
                let d = bytes[i];
                let sign_after_exponent =
                    (d == b'-' || d == b'+') && matches!(bytes[i - 1], b'e' | b'E');
                if d.is_ascii_digit() || d == b'.' || d == b'e' || d == b'E' || sign_after_exponent
                {
                    i += 1;
                } else {
                    break;
                }
            }
            let token = &text[start..i];
            if token.contains(['.', 'e', 'E']) {
                values.push(token.parse().map_err(|_| format!("bad number '{token}'"))?);
            }
        } else {
            i += 1;
        }
    }
    Ok(values)
}

/// The text without `//` and `/* */` comments.
fn strip_comments(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while !rest.is_empty() {
        if let Some(r) = rest.strip_prefix("//") {
            rest = r.find('\n').map_or("", |i| &r[i..]);
        } else if let Some(r) = rest.strip_prefix("/*") {
            rest = r.find("*/").map_or("", |i| &r[i + 2..]);
        } else {
            let c = rest.chars().next().expect("not empty");
            out.push(c);
            rest = &rest[c.len_utf8()..];
        }
    }
    out
}

fn read_source(text: &str) -> Result<LutData, String> {
    let line = text
        .lines()
        .find_map(|l| l.split_once(SOURCE_TAG).map(|(_, m)| m))
        .ok_or("no 'microsurface-lut:' line: not a table written by microsurface")?;
    let meta = Meta::parse(line)?;
    let expected = meta
        .nodes()?
        .checked_mul(meta.channels.len())
        .ok_or("the dims overflow")?;
    let code = strip_comments(text);
    let (_, init) = code.split_once('=').ok_or("no '=' after the declaration")?;
    // Up to the declaration's ';': without it the file was cut, maybe inside the last number.
    let (init, _) = init
        .split_once(';')
        .ok_or("no ';' closing the array: a truncated file")?;
    let values = float_tokens(init)?;
    if values.len() != expected {
        return Err(format!(
            "{} numbers for dims {:?} × {} channels",
            values.len(),
            meta.dims,
            meta.channels.len()
        ));
    }
    Ok(meta.with_values(values))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::PathBuf;

    /// A fresh directory of this process and test (no tempfile crate), removed by `Drop`.
    struct TempDir(PathBuf);

    impl TempDir {
        fn new(test: &str) -> TempDir {
            let dir = std::env::temp_dir()
                .join(format!("microsurface-lut-{}-{test}", std::process::id()));
            let _ = std::fs::remove_dir_all(&dir);
            std::fs::create_dir_all(&dir).unwrap();
            TempDir(dir)
        }
    }

    impl Drop for TempDir {
        fn drop(&mut self) {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }

    /// Deterministic values in [0, 1] (SplitMix64), opening with the edge cases: 0, 1, a
    /// subnormal and 0.5 exactly.
    fn table(dims: &[usize], channels: usize, seed: u64) -> LutData {
        let count = dims.iter().product::<usize>() * channels;
        let mut state = seed;
        let mut values: Vec<f32> = (0..count)
            .map(|_| {
                state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
                let mut z = state;
                z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
                z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
                ((z ^ (z >> 31)) >> 40) as f32 / (1u64 << 24) as f32
            })
            .collect();
        for (v, edge) in values.iter_mut().zip([0.0, 1.0, 1e-40, 0.5]) {
            *v = edge;
        }
        let axes = ["side", "eta", "sqrt_alpha", "mu"];
        LutData {
            name: "test_lut".into(),
            axes: axes[4 - dims.len()..]
                .iter()
                .map(|s| s.to_string())
                .collect(),
            dims: dims.to_vec(),
            channels: ["A", "B", "C", "D"][..channels]
                .iter()
                .map(|s| s.to_string())
                .collect(),
            values,
        }
    }

    /// 2, 3 and 4 axes; a last axis of at most 4 nodes (the `.npy` channel-axis rule's edge).
    const DIMS: [&[usize]; 6] = [
        &[5, 7],
        &[6, 3],
        &[3, 4, 6],
        &[2, 5, 3],
        &[2, 3, 4, 5],
        &[2, 2, 3, 4],
    ];

    fn check_roundtrip(data: &LutData, back: &LutData, format: Format) {
        let what = format!("{format} {:?} × {}", data.dims, data.channels.len());
        assert_eq!(back.dims, data.dims, "{what}");
        assert_eq!(back.values.len(), data.values.len(), "{what}");
        if format == Format::Npy {
            assert_eq!(back.channels.len(), data.channels.len(), "{what}");
            assert_eq!(back.name, "test_lut", "{what}: the stem");
        } else {
            assert_eq!(
                (&back.name, &back.axes, &back.channels),
                (&data.name, &data.axes, &data.channels),
                "{what}"
            );
        }
        for (i, (&v, &r)) in data.values.iter().zip(&back.values).enumerate() {
            if format.is_exact() {
                assert_eq!(r.to_bits(), v.to_bits(), "{what}: value {i}: {r} for {v}");
            } else {
                let q = (f64::from(v) * 65535.0).round() as u16;
                assert_eq!(r, f32::from(q) / 65535.0, "{what}: value {i}");
                assert!(
                    (r - v).abs() <= 0.5 / 65535.0 + f32::EPSILON,
                    "{what}: value {i}: {r} for {v}"
                );
            }
        }
    }

    #[test]
    fn lut_every_format_reads_back_what_it_wrote() {
        let dir = TempDir::new("roundtrip");
        for format in Format::ALL {
            for (d, dims) in DIMS.iter().enumerate() {
                for channels in 1..=4 {
                    let data = table(dims, channels, (d * 4 + channels) as u64);
                    let sub = dir.0.join(format!("{format}_{d}_{channels}"));
                    std::fs::create_dir(&sub).unwrap();
                    let path = sub.join(format!("test_lut.{}", format.extension()));
                    write(&data, format, &path).unwrap();
                    let back = read(format, &path).unwrap_or_else(|e| panic!("{format}: {e}"));
                    check_roundtrip(&data, &back, format);
                }
            }
        }
    }

    #[test]
    fn lut_png_rejects_values_outside_the_unit_interval() {
        let dir = TempDir::new("png_range");
        for bad in [1.5, -1e-7, 1.0000001] {
            let mut data = table(&[3, 4], 2, 7);
            data.values[5] = bad;
            let path = dir.0.join("bad.png");
            let err = write(&data, Format::Png16, &path).unwrap_err();
            assert!(err.contains("[0, 1]") && err.contains("channel B"), "{err}");
            assert!(!path.exists(), "no file after a bad value");
            assert!(!err.contains('\n'));
        }
    }

    #[test]
    fn lut_bad_tables_are_errors() {
        let dir = TempDir::new("bad_tables");
        let good = table(&[3, 4], 2, 1);
        let mut cases = Vec::new();
        let mut t = good.clone();
        t.values.pop();
        cases.push(t);
        let mut t = good.clone();
        t.dims = vec![12];
        t.axes = vec!["mu".into()];
        cases.push(t);
        let mut t = good.clone();
        t.channels = (0..5).map(|i| format!("c{i}")).collect();
        cases.push(t);
        let mut t = good.clone();
        t.name = "2bad name".into();
        cases.push(t);
        let mut t = good.clone();
        t.axes.pop();
        cases.push(t);
        let mut t = good.clone();
        t.values[3] = f32::NAN;
        cases.push(t);
        for (i, case) in cases.iter().enumerate() {
            for format in Format::ALL {
                let path = dir.0.join(format!("case{i}.{}", format.extension()));
                let err = write(case, format, &path).unwrap_err();
                assert!(!err.is_empty() && !err.contains('\n'), "{err}");
            }
        }
        let missing = dir.0.join("no_such_dir").join("t.npy");
        for format in Format::ALL {
            assert!(
                write(&good, format, &missing.with_extension(format.extension())).is_err(),
                "{format}"
            );
            assert!(read(format, &missing).is_err());
        }
    }

    /// Truncated, empty and garbage files give an error or, where the cut removed nothing that
    /// matters (a source file's last newline, a PNG's end chunk), the table: never a panic and
    /// never other values.
    #[test]
    fn lut_truncated_and_garbage_files_are_errors() {
        let dir = TempDir::new("truncated");
        for format in Format::ALL {
            for (dims, channels) in [(&[2, 3, 4, 5][..], 3), (&[4, 6][..], 1)] {
                let data = table(dims, channels, 11);
                let path = dir.0.join(format!("whole.{}", format.extension()));
                write(&data, format, &path).unwrap();
                let bytes = std::fs::read(&path).unwrap();
                let n = bytes.len();
                let mut cuts = vec![
                    0,
                    1,
                    6,
                    10,
                    12,
                    40,
                    79,
                    80,
                    100,
                    120,
                    n / 3,
                    n / 2,
                    n - 8,
                    n - 4,
                    n - 1,
                ];
                cuts.retain(|&c| c < n);
                for cut in cuts {
                    let cut_path = dir.0.join(format!("cut{cut}.{}", format.extension()));
                    std::fs::write(&cut_path, &bytes[..cut]).unwrap();
                    match read(format, &cut_path) {
                        Err(e) => assert!(!e.contains('\n'), "{e}"),
                        Ok(back) => check_roundtrip(&data, &back, format),
                    }
                }
                // Flipped bytes in the middle: an error or well-formed data, never a panic.
                let mut flipped = bytes.clone();
                for b in flipped.iter_mut().skip(n / 4).step_by(7).take(64) {
                    *b ^= 0x5A;
                }
                let flipped_path = dir.0.join(format!("flipped.{}", format.extension()));
                std::fs::write(&flipped_path, &flipped).unwrap();
                let _ = read(format, &flipped_path);
            }
            let garbage: Vec<u8> = (0..4096u32)
                .map(|i| (i.wrapping_mul(2_654_435_761) >> 13) as u8)
                .collect();
            let path = dir.0.join(format!("garbage.{}", format.extension()));
            std::fs::write(&path, &garbage).unwrap();
            assert!(read(format, &path).is_err(), "{format}");
        }
    }

    #[test]
    fn lut_absurd_metadata_is_an_error() {
        let dir = TempDir::new("absurd");
        let path = dir.0.join("t.h");
        let huge = usize::MAX / 2;
        let text = format!(
            "// microsurface-lut: name=t;axes=a,b;dims={huge},1;channels=A,B,C,D\n\
             static const float t[1][1] = {{0.5f}};\n"
        );
        std::fs::write(&path, text).unwrap();
        let err = read(Format::C, &path).unwrap_err();
        assert!(err.contains("overflow"), "{err}");
    }

    #[test]
    fn lut_format_names() {
        for format in Format::ALL {
            assert_eq!(format.name().parse::<Format>(), Ok(format));
            assert_eq!(format.to_string(), format.name());
        }
        assert_eq!("KTX2".parse::<Format>(), Ok(Format::Ktx2));
        let err = "tiff".parse::<Format>().unwrap_err();
        assert!(
            err.contains("tiff") && err.contains("npy, png, exr, ktx2, c, rust, wgsl"),
            "{err}"
        );
        assert_eq!(
            Format::ALL
                .iter()
                .filter(|f| !f.is_exact())
                .collect::<Vec<_>>(),
            [&Format::Png16]
        );
    }

    #[test]
    fn lut_npy_header() {
        let dir = TempDir::new("npy");
        for (dims, channels, shape) in [
            (&[5, 7][..], 1, "(5, 7)"),
            (&[5, 7][..], 3, "(5, 7, 3)"),
            (&[2, 5, 7][..], 1, "(2, 5, 7)"),
            (&[2, 5, 3][..], 1, "(2, 5, 3, 1)"),
            (&[2, 2, 5, 3][..], 1, "(2, 2, 5, 3, 1)"),
        ] {
            let path = dir.0.join("t.npy");
            write(&table(dims, channels, 3), Format::Npy, &path).unwrap();
            let bytes = std::fs::read(&path).unwrap();
            assert_eq!(&bytes[..8], b"\x93NUMPY\x01\x00");
            let header_len = usize::from(u16::from_le_bytes([bytes[8], bytes[9]]));
            assert_eq!((10 + header_len) % 64, 0);
            let header = std::str::from_utf8(&bytes[10..10 + header_len]).unwrap();
            let expected =
                format!("{{'descr': '<f4', 'fortran_order': False, 'shape': {shape}, }}");
            assert_eq!(header.trim_end_matches([' ', '\n']), expected);
            assert!(header.ends_with('\n'));
        }
    }

    fn u32_at(bytes: &[u8], at: usize) -> u32 {
        u32::from_le_bytes(bytes[at..at + 4].try_into().unwrap())
    }

    fn u64_at(bytes: &[u8], at: usize) -> u64 {
        u64::from_le_bytes(bytes[at..at + 8].try_into().unwrap())
    }

    /// The byte layout of the KTX 2.0 spec, field by field.
    #[test]
    fn lut_ktx2_layout() {
        let data = table(&[2, 3, 4, 5], 3, 5);
        let bytes = ktx2_bytes(&data).unwrap();
        assert_eq!(bytes[..12], KTX2_IDENTIFIER);
        let header: Vec<u32> = (0..9).map(|i| u32_at(&bytes, 12 + 4 * i)).collect();
        // vkFormat R32G32B32A32_SFLOAT, typeSize, width μ, height, depth, layers, faces, levels, scheme
        assert_eq!(header, [109, 4, 5, 4, 3, 2, 1, 1, 0]);
        let (dfd_offset, dfd_len) = (u32_at(&bytes, 48) as usize, u32_at(&bytes, 52) as usize);
        let (kvd_offset, kvd_len) = (u32_at(&bytes, 56) as usize, u32_at(&bytes, 60) as usize);
        assert_eq!(
            (u64_at(&bytes, 64), u64_at(&bytes, 72)),
            (0, 0),
            "no supercompression global data"
        );
        assert_eq!(dfd_offset, 80 + 24, "the DFD follows the one-level index");
        assert_eq!(dfd_len, 4 + 24 + 4 * 16);
        assert_eq!(kvd_offset, dfd_offset + dfd_len);
        let (level_offset, level_len) = (u64_at(&bytes, 80) as usize, u64_at(&bytes, 88) as usize);
        assert_eq!(
            u64_at(&bytes, 96) as usize,
            level_len,
            "uncompressedByteLength"
        );
        assert_eq!(level_len, 2 * 3 * 4 * 5 * 16);
        assert_eq!(
            level_offset % 16,
            0,
            "mipPadding: lcm(texel block size 16, 4)"
        );
        assert!(level_offset >= kvd_offset + kvd_len && level_offset < kvd_offset + kvd_len + 16);
        assert_eq!(level_offset + level_len, bytes.len());
        // The basic DFD block.
        let dfd: Vec<u32> = (0..dfd_len / 4)
            .map(|i| u32_at(&bytes, dfd_offset + 4 * i))
            .collect();
        assert_eq!(
            dfd[..7],
            [92, 0, 2 | (88 << 16), 1 | (1 << 8) | (1 << 16), 0, 16, 0]
        );
        for (k, id) in [0u32, 1, 2, 15].into_iter().enumerate() {
            let s = &dfd[7 + 4 * k..11 + 4 * k];
            assert_eq!(
                s,
                [
                    (32 * k as u32) | (31 << 16) | ((id | 0xC0) << 24),
                    0,
                    0xBF80_0000,
                    0x3F80_0000
                ]
            );
        }
        // Key/value data: sorted keys, NUL-terminated values, each entry padded to 4.
        let kvd = &bytes[kvd_offset..kvd_offset + kvd_len];
        let first_len = u32_at(kvd, 0) as usize;
        let writer = format!("KTXwriter\0microsurface {}\0", env!("CARGO_PKG_VERSION"));
        assert_eq!(&kvd[4..4 + first_len], writer.as_bytes());
        let second = (4 + first_len).next_multiple_of(4);
        let second_len = u32_at(kvd, second) as usize;
        let meta = format!("microsurface\0{}\0", data.meta());
        assert_eq!(&kvd[second + 4..second + 4 + second_len], meta.as_bytes());
        assert_eq!(kvd_len, (second + 4 + second_len).next_multiple_of(4));
        // The texels: channels padded with 0 to four.
        let texel = &bytes[level_offset + 16..level_offset + 32];
        let texel: Vec<f32> = texel
            .chunks_exact(4)
            .map(|b| f32::from_le_bytes(b.try_into().unwrap()))
            .collect();
        assert_eq!(texel, [data.values[3], data.values[4], data.values[5], 0.0]);
        // 2 axes: a 2D texture; 3 axes: a 3D one.
        for (dims, expected) in [(&[4, 5][..], [5, 4, 0, 0]), (&[3, 4, 5][..], [5, 4, 3, 0])] {
            let bytes = ktx2_bytes(&table(dims, 1, 1)).unwrap();
            let extents: Vec<u32> = (0..4).map(|i| u32_at(&bytes, 20 + 4 * i)).collect();
            assert_eq!(extents, expected);
            assert_eq!(u32_at(&bytes, 12), 100, "R32_SFLOAT");
        }
    }

    #[test]
    fn lut_source_arrays_declare_what_the_docs_say() {
        let data = table(&[2, 3], 3, 9);
        let c = source(&data, Format::C);
        assert!(
            c.contains("static const float test_lut[2][3][3] = {"),
            "{c}"
        );
        assert!(c.contains("{0.0f, 1.0f, 1e-40f}"), "{c}");
        let rust = source(&data, Format::Rust);
        assert!(
            rust.contains("pub static TEST_LUT: [[[f32; 3]; 3]; 2] = ["),
            "{rust}"
        );
        assert!(rust.contains("[0.0, 1.0, 1e-40]"), "{rust}");
        let wgsl = source(&data, Format::Wgsl);
        assert!(
            wgsl.contains("const TEST_LUT: array<vec3<f32>, 6> = array<vec3<f32>, 6>("),
            "{wgsl}"
        );
        assert!(
            wgsl.contains("TEST_LUT[(i_sqrt_alpha) * 3u + i_mu]"),
            "{wgsl}"
        );
        assert!(wgsl.contains("vec3<f32>(0.0f, 1.0f, 1e-40f)"), "{wgsl}");
        let one = source(&table(&[2, 3], 1, 9), Format::C);
        assert!(
            one.contains("static const float test_lut[2][3] = {"),
            "{one}"
        );
    }
}
