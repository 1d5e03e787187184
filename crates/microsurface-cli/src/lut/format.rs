//! Placeholder: npy only (the real module replaces this file).

use std::path::Path;
use std::str::FromStr;

pub struct LutData {
    pub name: String,
    pub axes: Vec<String>,
    pub dims: Vec<usize>,
    pub channels: Vec<String>,
    pub values: Vec<f32>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Npy,
}

impl Format {
    pub const ALL: [Format; 1] = [Format::Npy];
    pub fn extension(self) -> &'static str {
        "npy"
    }
}

impl FromStr for Format {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "npy" => Ok(Format::Npy),
            _ => Err(format!("unknown format '{s}'")),
        }
    }
}

pub fn write(data: &LutData, _format: Format, path: &Path) -> Result<(), String> {
    let mut shape: Vec<usize> = data.dims.clone();
    shape.push(data.channels.len());
    let shape: Vec<String> = shape.iter().map(|d| d.to_string()).collect();
    let mut header = format!(
        "{{'descr': '<f4', 'fortran_order': False, 'shape': ({},), }}",
        shape.join(", ")
    );
    while (10 + header.len() + 1) % 64 != 0 {
        header.push(' ');
    }
    header.push('\n');
    let mut bytes = b"\x93NUMPY\x01\x00".to_vec();
    bytes.extend((header.len() as u16).to_le_bytes());
    bytes.extend(header.as_bytes());
    for v in &data.values {
        bytes.extend(v.to_le_bytes());
    }
    std::fs::write(path, bytes).map_err(|e| e.to_string())
}

pub fn read(_format: Format, path: &Path) -> Result<LutData, String> {
    let bytes = std::fs::read(path).map_err(|e| e.to_string())?;
    let len = u16::from_le_bytes([bytes[8], bytes[9]]) as usize;
    let header = std::str::from_utf8(&bytes[10..10 + len]).map_err(|e| e.to_string())?;
    let shape = header.split('(').nth(1).unwrap().split(')').next().unwrap();
    let mut dims: Vec<usize> = shape
        .split(',')
        .filter_map(|s| s.trim().parse().ok())
        .collect();
    let c = dims.pop().unwrap();
    let values = bytes[10 + len..]
        .chunks_exact(4)
        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    Ok(LutData {
        name: String::new(),
        axes: Vec::new(),
        dims,
        channels: vec![String::new(); c],
        values,
    })
}
