//! GGX's fast paths for the functions of a cosine: D, Λ and G1 of the `NDF` classes run
//! the library's closed forms (`microsurface::fast::ggx`) and their slice forms
//! (`microsurface::fast::batch`, within 3e-15 of the exact path), in f32 arithmetic for
//! float32 input ([`kernel_f32`]), in blocks of [`BLOCK`] elements.

use crate::engine::{self, float64, is_number, Args, Domain, PARALLEL};
use microsurface::NdfKind;
use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;

/// The quantities with fast paths.
#[derive(Clone, Copy)]
pub enum Q {
    D,
    Lambda,
    G1,
}

/// A quantity with a fast path in the library: its scalar function and slice form
/// (`microsurface::fast`), used where they are the closed form itself (GGX's D, Λ and G1:
/// within 2e-15 of the exact path, and the slice form bit-equal to the scalar one).
#[derive(Clone, Copy)]
pub struct Kernel {
    scalar: fn(f64, f64) -> f64,
    slice: fn(&[f64], &[f64], &mut [f64]),
    slice32: fn(&[f32], &[f32], &mut [f32]),
}

impl Kernel {
    /// The fast path of quantity q of an NDF of `kind`, where it is the closed form (GGX).
    pub fn of(kind: NdfKind, q: Q) -> Option<Self> {
        use microsurface::fast::{batch, ggx};
        if kind != NdfKind::Ggx {
            return None;
        }
        Some(match q {
            Q::D => Kernel {
                scalar: ggx::d::<f64>,
                slice: batch::ggx_d,
                slice32: batch::ggx_d_f32,
            },
            Q::Lambda => Kernel {
                scalar: ggx::lambda::<f64>,
                slice: batch::ggx_lambda,
                slice32: batch::ggx_lambda_f32,
            },
            Q::G1 => Kernel {
                scalar: ggx::g1::<f64>,
                slice: batch::ggx_g1,
                slice32: batch::ggx_g1_f32,
            },
        })
    }
}

/// Elements a slice kernel takes at a time (L1-resident, with the constant-α buffer).
pub const BLOCK: usize = 4096;

/// Heitz's extension of Λ below the horizon, Λ(u) = −1 − Λ(|u|) for u < 0, over a block
/// whose kernel gave Λ(|u|) (a select, branch-free; −0 keeps Λ(0) = +∞).
fn odd<T: Copy + PartialOrd + Default + std::ops::Neg<Output = T> + std::ops::Sub<Output = T>>(
    u: &[T],
    out: &mut [T],
    one: T,
) {
    for (o, &u) in out.iter_mut().zip(u) {
        let reflected = -one - *o;
        *o = if u < T::default() { reflected } else { *o };
    }
}

/// `kernel` over u (a cosine; and an array α, validated, if given; else `alpha0`), with the
/// engine's domains: NaN gives NaN (the closed forms propagate it), u outside [−1, 1] and a
/// bad α raise ValueError. `lambda`: the kernel is Λ, extended below the horizon as the
/// library's `Ndf::lambda` (−1 − Λ(|u|)).
pub fn apply_kernel<'py>(
    py: Python<'py>,
    u: &Bound<'py, PyAny>,
    alpha: Option<&Bound<'py, PyAny>>,
    alpha0: f64,
    k: Kernel,
    lambda: bool,
) -> PyResult<PyObject> {
    let mut items = vec![(u, 0, "u", Domain::Cosine)];
    if let Some(a) = alpha {
        items.push((a, 0, "alpha", engine::FIXED));
    }
    if is_number(u) && alpha.is_none_or(|a| is_number(a)) {
        let x = u.extract::<f64>()?;
        let a = match alpha {
            Some(a) => a.extract::<f64>()?,
            None => alpha0,
        };
        engine::check_numbers(py, &items, &[x, a])?;
        let mut y = [(k.scalar)(x, a)];
        if lambda {
            odd(&[x], &mut y, 1.0);
        }
        return Ok(float64(py)?.call1((y[0],))?.unbind());
    }
    // u float32: the f32 slice forms (α rounded to f32, as a renderer's f32 material).
    let np = engine::numpy(py)?;
    let float32 = np.getattr("float32")?;
    let ua = np.call_method1("asarray", (u,))?;
    if ua.getattr("dtype")?.eq(&float32)? {
        let aa = alpha
            .map(|a| np.call_method1("asarray", (a, &float32)))
            .transpose()?;
        return kernel_f32(py, &ua, aa.as_ref(), alpha0, k, lambda, &items);
    }
    let a = Args::new(py, &items)?;
    let us = a.slice(0)?;
    let alphas = if alpha.is_some() {
        Some(a.slice(1)?)
    } else {
        None
    };
    let constant = vec![alpha0; BLOCK.min(us.len())];
    let mut out = a.run_blocks(py, 1, &[0], BLOCK, PARALLEL, |start, out| {
        let u = &us[start..start + out.len()];
        let al = match alphas {
            Some(al) => &al[start..start + out.len()],
            None => &constant[..out.len()],
        };
        (k.slice)(u, al, out);
        if lambda {
            odd(u, out, 1.0);
        }
        Ok(())
    })?;
    Ok(out.remove(0))
}

/// `kernel` over float32 arrays in f32 (the library's f32 slice forms; α rounded to f32, or
/// the float32 array `alpha`, broadcast with u), without copies of contiguous input; `items`
/// (u's and α's names and domains) checked as the engine checks float64 arrays.
fn kernel_f32<'py>(
    py: Python<'py>,
    u: &Bound<'py, PyAny>,
    alpha: Option<&Bound<'py, PyAny>>,
    alpha0: f64,
    k: Kernel,
    lambda: bool,
    items: &[engine::Item<'_, 'py>],
) -> PyResult<PyObject> {
    let np = engine::numpy(py)?;
    let flat = |a: &Bound<'py, PyAny>| -> PyResult<Bound<'py, PyArray1<f32>>> {
        Ok(np
            .call_method1("ascontiguousarray", (a,))?
            .call_method1("reshape", (-1,))?
            .downcast_into::<PyArray1<f32>>()?)
    };
    let (u, alpha, shape) = match alpha {
        None => (flat(u)?, None, u.getattr("shape")?),
        Some(a) => {
            let b = np.call_method1("broadcast_arrays", (u, a))?;
            let ub = b.get_item(0)?;
            let shape = ub.getattr("shape")?;
            (flat(&ub)?, Some(flat(&b.get_item(1)?)?), shape)
        }
    };
    let (ro, ra) = (u.readonly(), alpha.as_ref().map(|a| a.readonly()));
    let us = ro.as_slice()?;
    let als = ra.as_ref().map(|r| r.as_slice()).transpose()?;
    engine::check_domain(py, us, items[0].2, items[0].3, items[0].0, true)?;
    if let Some(al) = als {
        engine::check_domain(py, al, items[1].2, items[1].3, items[1].0, true)?;
    }
    let constant = [alpha0 as f32; BLOCK];
    let out =
        engine::compute_blocks_of(py, us.len(), 1, BLOCK, PARALLEL, "float32", |start, o| {
            let n = o.len();
            let al = match als {
                Some(al) => &al[start..start + n],
                None => &constant[..n],
            };
            (k.slice32)(&us[start..start + n], al, o);
            if lambda {
                odd(&us[start..start + n], o, 1.0f32);
            }
            Ok(())
        })?;
    let mut result = out.into_any().call_method1("reshape", (shape,))?;
    if result.getattr("ndim")?.extract::<usize>()? == 0 {
        // (A NumPy scalar, as a ufunc gives for scalar input.)
        result = result.get_item(())?;
    }
    Ok(result.unbind())
}
