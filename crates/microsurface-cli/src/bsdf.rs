//! `microsurface bsdf`: the rough conductor and dielectric BSDFs, single scattering or with
//! multiple scattering ("scattering": single, kulla_conty, turquin, walk), JSON lines in, one
//! line out per line, in order (errors as in `eval`). Local frame, z = normal; radiance
//! transport; f64. Every combination is the library's `Box<dyn Bsdf<f64, Value = [f64; 3]>>`.

use crate::json::{array, direction, field, ndf_alpha, spectrum, string};
use microsurface::bsdf::fresnel::{self, One};
use microsurface::bsdf::{Bsdf, BsdfSample, Lobe, Masking, RoughConductor, RoughDielectric};
use microsurface::scattering::{ByOrder, DielectricFacets, MirrorFacets, MultipleScattering};
use microsurface::scattering::{CompensatedConductor, CompensatedDielectric, Scheme};
use microsurface::{AnyMicrofacet, MicrofacetDistribution};
use serde_json::{json, Map, Value};
use std::process::ExitCode;

pub fn run(args: &[String]) -> Result<ExitCode, String> {
    crate::json::json_lines("bsdf", args, bsdf_line)
}

const FIELDS: [&str; 15] = [
    "bsdf",
    "ndf",
    "alpha",
    "gamma",
    "a",
    "eta",
    "k",
    "g2",
    "op",
    "wo",
    "wi",
    "u",
    "samples",
    "seed",
    "scattering",
];

/// Which BSDF of the material: single scattering, or multiple scattering by one of the
/// library's models.
#[derive(Clone, Copy, PartialEq)]
enum Scattering {
    Single,
    Compensated(Scheme),
    Walk,
}

/// Samples per eval_ms line at most (10⁹: minutes; a typo's 10²⁰ is an error, not a hang).
const MAX_SAMPLES: f64 = 1e9;

/// Answers one request line (GTR's and the family's fits are cached by the library, so a
/// line of a material seen before does not fit again).
fn bsdf_line(text: &str) -> Result<Value, String> {
    let v: Value = serde_json::from_str(text).map_err(|e| format!("not valid JSON: {e}"))?;
    let obj = v.as_object().ok_or("expected a JSON object")?;
    crate::json::known_fields(obj, &FIELDS)?;
    let req = Request::parse(obj)?;
    let (kind, ax, ay, shape) = ndf_alpha(obj)?;
    req.answer(AnyMicrofacet::<f64>::new(kind, ax, ay, shape).map_err(|e| e.to_string())?)
}

#[derive(Clone, Copy)]
enum Material {
    /// F = 1 (no eta, no k).
    Mirror,
    Metal {
        eta: [f64; 3],
        k: [f64; 3],
    },
    Glass {
        eta: f64,
    },
}

enum Op {
    Eval {
        wo: [f64; 3],
        wi: [f64; 3],
    },
    Sample {
        wo: [f64; 3],
        u: [f64; 3],
    },
    /// The multiple-scattering BSDF by order (the random walk's stochastic evaluation).
    EvalMs {
        wo: [f64; 3],
        wi: [f64; 3],
        samples: u64,
        seed: u64,
    },
}

struct Request {
    material: Material,
    masking: Masking,
    scattering: Scattering,
    op: Op,
}

impl Request {
    fn parse(obj: &Map<String, Value>) -> Result<Self, String> {
        let material = match string(obj, "bsdf")? {
            "conductor" => match (obj.contains_key("eta"), obj.contains_key("k")) {
                (false, false) => Material::Mirror,
                (true, true) => {
                    let (eta, k) = (spectrum(obj, "eta")?, spectrum(obj, "k")?);
                    if eta.iter().any(|&e| e <= 0.0) || k.iter().any(|&k| k < 0.0) {
                        return Err("a conductor needs eta > 0 and k >= 0".into());
                    }
                    Material::Metal { eta, k }
                }
                _ => return Err("a conductor takes both 'eta' and 'k', or neither (F = 1)".into()),
            },
            "dielectric" => {
                if obj.contains_key("k") {
                    return Err("field 'k' is for conductors only".into());
                }
                let eta = match obj.get("eta") {
                    Some(Value::Array(_)) => {
                        return Err(
                            "a dielectric's 'eta' is one number (the same in every channel)".into(),
                        )
                    }
                    _ => field(obj, "eta")?,
                };
                if !(eta > 0.0 && eta.is_finite()) {
                    return Err(format!(
                        "a dielectric needs a finite eta > 0, got {}",
                        crate::json::num(eta)
                    ));
                }
                Material::Glass { eta }
            }
            other => {
                return Err(format!(
                    "unknown bsdf '{}' (expected conductor or dielectric)",
                    crate::clip(other)
                ))
            }
        };
        let masking = crate::json::masking(obj, Masking::Correlated)?;
        let scattering = match obj.get("scattering") {
            None => Scattering::Single,
            Some(v) => match v.as_str() {
                Some("single") => Scattering::Single,
                Some("kulla_conty") => Scattering::Compensated(Scheme::KullaConty),
                Some("turquin") => Scattering::Compensated(Scheme::Turquin),
                Some("walk") => Scattering::Walk,
                _ => {
                    return Err(
                        "field 'scattering' must be \"single\", \"kulla_conty\", \"turquin\" or \"walk\""
                            .into(),
                    )
                }
            },
        };
        if scattering != Scattering::Single && masking != Masking::Correlated {
            return Err(
                "multiple scattering (the compensations and the walk) is height-correlated: no 'g2'"
                    .into(),
            );
        }
        let op_name = string(obj, "op")?;
        if op_name == "eval_ms" && obj.contains_key("scattering") {
            return Err("op eval_ms is the random walk by order: no 'scattering'".into());
        }
        if op_name != "eval_ms" && (obj.contains_key("samples") || obj.contains_key("seed")) {
            return Err("fields 'samples' and 'seed' are for op eval_ms".into());
        }
        let op = match op_name {
            "eval_ms" => {
                if obj.contains_key("u") {
                    return Err("field 'u' is for op sample".into());
                }
                if masking != Masking::Correlated {
                    return Err(
                        "op eval_ms is the random walk, whose G2 is height-correlated (no 'g2')"
                            .into(),
                    );
                }
                let samples = crate::json::count(obj, "samples", MAX_SAMPLES, "1e9")?;
                let seed = crate::json::seed(obj)?;
                Op::EvalMs {
                    wo: direction(obj, "wo")?,
                    wi: direction(obj, "wi")?,
                    samples,
                    seed,
                }
            }
            "eval" => {
                if obj.contains_key("u") {
                    return Err("field 'u' is for op sample".into());
                }
                Op::Eval {
                    wo: direction(obj, "wo")?,
                    wi: direction(obj, "wi")?,
                }
            }
            "sample" => {
                if obj.contains_key("wi") {
                    return Err("field 'wi' is for op eval".into());
                }
                let u = array(obj, "u", 3)?;
                if u.iter().any(|&x| !(0.0..1.0).contains(&x)) {
                    return Err("field 'u' must hold three numbers in [0, 1)".into());
                }
                Op::Sample {
                    wo: direction(obj, "wo")?,
                    u: [u[0], u[1], u[2]],
                }
            }
            other => {
                return Err(format!(
                    "unknown op '{}' (expected eval, sample or eval_ms)",
                    crate::clip(other)
                ))
            }
        };
        Ok(Request {
            material,
            masking,
            scattering,
            op,
        })
    }

    fn answer<D: MicrofacetDistribution<f64> + Clone + 'static>(
        &self,
        d: D,
    ) -> Result<Value, String> {
        if let Op::EvalMs {
            wo,
            wi,
            samples,
            seed,
        } = self.op
        {
            let by_order = match self.material {
                Material::Mirror => MultipleScattering::new(d, MirrorFacets(One::<3>))
                    .eval_orders(wo, wi, samples, seed),
                Material::Metal { eta, k } => {
                    MultipleScattering::new(d, MirrorFacets(fresnel::Conductor { eta, k }))
                        .eval_orders(wo, wi, samples, seed)
                }
                Material::Glass { eta } => {
                    let [b] = MultipleScattering::new(
                        d,
                        DielectricFacets::new(eta).map_err(|e| e.to_string())?,
                    )
                    .eval_orders(wo, wi, samples, seed);
                    [b; 3]
                }
            };
            let per = |f: &dyn Fn(&ByOrder) -> f64| by_order.map(|b| f(&b));
            let orders: Vec<[f64; 3]> = (0..4).map(|k| per(&|b| b.orders[k])).collect();
            let stderr: Vec<[f64; 3]> = (0..4).map(|k| per(&|b| b.stderr[k])).collect();
            return Ok(json!({
                "orders": orders,
                "stderr": stderr,
                "total": per(&|b| b.total),
                "total_stderr": per(&|b| b.total_stderr),
            }));
        }
        self.run(self.bsdf(d)?.as_ref())
    }

    /// The material's BSDF for the request's scattering model.
    fn bsdf<D: MicrofacetDistribution<f64> + Clone + 'static>(
        &self,
        d: D,
    ) -> Result<Box<dyn Bsdf<f64, Value = [f64; 3]>>, String> {
        let m = self.masking;
        let err = |e: microsurface::ParamError| e.to_string();
        Ok(match (self.material, self.scattering) {
            (Material::Mirror, Scattering::Single) => {
                Box::new(RoughConductor::new(d, One::<3>).with_masking(m))
            }
            (Material::Metal { eta, k }, Scattering::Single) => {
                Box::new(RoughConductor::new(d, fresnel::Conductor { eta, k }).with_masking(m))
            }
            (Material::Glass { eta }, Scattering::Single) => {
                Box::new(RoughDielectric::new(d, eta).map_err(err)?.with_masking(m))
            }
            (Material::Mirror, Scattering::Compensated(s)) => {
                Box::new(CompensatedConductor::new(d, One::<3>, s))
            }
            (Material::Metal { eta, k }, Scattering::Compensated(s)) => Box::new(
                CompensatedConductor::new(d, fresnel::Conductor { eta, k }, s),
            ),
            (Material::Glass { eta }, Scattering::Compensated(s)) => {
                Box::new(CompensatedDielectric::new(d, eta, s).map_err(err)?)
            }
            (Material::Mirror, Scattering::Walk) => {
                Box::new(MultipleScattering::new(d, MirrorFacets(One::<3>)))
            }
            (Material::Metal { eta, k }, Scattering::Walk) => Box::new(MultipleScattering::new(
                d,
                MirrorFacets(fresnel::Conductor { eta, k }),
            )),
            (Material::Glass { eta }, Scattering::Walk) => Box::new(MultipleScattering::new(
                d,
                DielectricFacets::new(eta).map_err(err)?,
            )),
        })
    }

    fn run(&self, b: &dyn Bsdf<f64, Value = [f64; 3]>) -> Result<Value, String> {
        match self.op {
            Op::Eval { wo, wi } => Ok(json!({ "f": b.eval(wo, wi), "pdf": b.pdf(wo, wi) })),
            Op::EvalMs { .. } => unreachable!("answered in `answer`"),
            Op::Sample { wo, u } => Ok(match b.sample(wo, u[0], [u[1], u[2]]) {
                Some(BsdfSample {
                    wi,
                    f,
                    pdf,
                    lobe,
                    specular,
                    ..
                }) => json!({
                    "wi": wi,
                    "f": f,
                    "pdf": pdf,
                    "kind": match lobe { Lobe::Reflection => "reflection", Lobe::Transmission => "transmission" },
                    "specular": specular,
                }),
                None => json!({ "wi": null, "f": [0.0, 0.0, 0.0], "pdf": 0.0, "kind": "rejected" }),
            }),
        }
    }
}
