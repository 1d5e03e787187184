//! `Tables::add_shape` at the edges of its contract: every shape answers with a table or a
//! typed error, never a panic; a table's header and rows are finite.

use microsurface::NdfKind;
use microsurface_gpu::{Tables, TABLES};

#[test]
fn add_shape_is_total_over_shapes_and_kinds() {
    let shapes = [
        None,
        Some(f64::NAN),
        Some(f64::INFINITY),
        Some(f64::NEG_INFINITY),
        Some(-1.0),
        Some(0.0),
        Some(1.0),
        Some(1.5),
        Some(1.5 + 1e-12),
        Some(1.500_001),
        Some(2.0),
        Some(2.5),
        Some(50.0),
        Some(1e6),
        Some(1e6 * (1.0 + 1e-15)),
        Some(1e300),
        Some(1e-3),
        Some(0.1),
        Some(0.999),
        Some(1.001),
        Some(100.0),
    ];
    let kinds = [
        NdfKind::Ggx,
        NdfKind::Beckmann,
        NdfKind::Gtr,
        NdfKind::DoubleGgx,
        NdfKind::Exponential,
        NdfKind::StudentT,
        NdfKind::Ei,
        NdfKind::Erfc,
        NdfKind::K0,
        NdfKind::BesselK,
        NdfKind::GenExponential,
    ];
    let mut tables = Tables::new();
    assert_eq!(tables.bytes(), TABLES);
    for &kind in &kinds {
        for &shape in &shapes {
            let before = tables.bytes().len();
            match tables.add_shape(kind, shape) {
                Ok(row) => {
                    match kind {
                        NdfKind::StudentT => {
                            let g = shape.expect("a shape");
                            assert!(g > 1.5 && g <= 1e6, "{g}");
                        }
                        NdfKind::Ei | NdfKind::Erfc | NdfKind::K0 | NdfKind::BesselK => {}
                        _ => panic!("{kind:?} {shape:?} has no GPU table"),
                    }
                    let g = shape.unwrap_or(0.0);
                    assert_eq!(row as usize * 16, before);
                    let added = &tables.bytes()[before..];
                    assert!(added.len() > 3 * 16);
                    for c in added.chunks_exact(4) {
                        let v = f32::from_le_bytes([c[0], c[1], c[2], c[3]]);
                        assert!(v.is_finite(), "γ = {g}: {v}");
                    }
                }
                Err(e) => {
                    assert_eq!(tables.bytes().len(), before, "{kind:?} {shape:?}: {e}");
                    assert!(!e.to_string().is_empty());
                }
            }
        }
    }
}
