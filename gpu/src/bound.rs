//! The error bound WGSL allows a function, derived from the function's own IR.
//!
//! [`Interp`] runs a naga function in `f64` on one row of `f32` arguments and carries, next
//! to each value, a bound on how far the `f32` value an implementation computes may lie from
//! it. Each operation adds the allowance the W3C WGSL specification's accuracy table gives it
//! (section "Floating Point Accuracy") to the errors it inherits from its operands:
//!
//! | operation | own allowance (units of the result's ULP, `f32`) | inherited |
//! |---|---|---|
//! | `+`, `-`, `*` | 0.5 (correctly rounded) + 0.5 | exact interval arithmetic |
//! | `x - y` of two operands, alone (no longer chain), whose intervals keep y / 2 <= x <= 2 y (or one operand exactly 0) | 0.5 on the result (exact by Sterbenz's lemma; the half ULP pays for a contraction of an inexact operand's product into an `fma`, which rounds once), none where both operands are exact | exact |
//! | `x * 2^k`, 2^k an exact operand | none (exact; a subnormal result: the 2^-126 below) | exact |
//! | `x + y`, `x * y` of two exact operands, alone (no longer chain), whose exact result is a normal `f32` (or 0) | none (every rounding, fused or not, returns it) | |
//! | `fma(2^k, u, c)`, 2^k and c exact, alone | the distance from the form's value to the roundings of 2^k u + c at u's interval's ends (none where both are that value: `2 u - 1` for u in [1/4, 1), at u = 0 and a subnormal u) | monotone in u |
//! | a `..._newton` helper (one Newton step on its first argument) | the step's evaluation error with its iterate exact (the largest at the interval's ends and centre) | the exact step's image of the iterate's interval: its ends, centre and fixed point ([`NEWTON_SUFFIX`]) |
//! | `round`, `floor` | none (correctly rounded, so exact); an argument interval that holds several integers' rounding ranges gives the alternatives below | |
//! | `fract` | `x - floor(x)`, the steps as above | |
//! | `x / y` | 2.5 (for \|y\| in [2^-126, 2^126], else no promise) + 0.5 | exact |
//! | `inverseSqrt` | 2 + 0.5 | endpoints (monotone) |
//! | `sqrt` | 1 / `inverseSqrt`: 2 ULP relative on the root is at most 4 ULP of it, the division 2.5, + 0.5 | endpoints |
//! | `exp`, `exp2` | 3 + 2 \|x\| + 0.5 | endpoints |
//! | `log`, `log2` | absolute 2^-21 for x in [0.5, 2], else 3 + 0.5 | endpoints |
//! | `pow(x, y)` | `exp2(y * log2(x))`, each step as above | |
//! | `sin`, `cos` | absolute 2^-11 for x in [-pi, pi] (no promise outside) + 0.5 | Lipschitz 1, per alternative |
//! | `asin` | `atan2(x, sqrt(1 - x * x))`: the steps as above, then 4096 + 0.5 | corners of the arguments' box |
//! | `acos` | `atan2(sqrt(1 - x * x), x)`: the steps as above, then 4096 + 0.5 | corners of the arguments' box |
//! | `fma(a, b, c)` | `a * b + c`, two roundings as above | |
//! | `min`, `max`, `clamp`, `saturate`, `abs`, negation | none (exact) | exact interval arithmetic |
//! | integer (`u32`, `i32`) `+`, `-`, `*` | none (exact where it does not wrap, which is asserted) | operands exact |
//! | `f32(i)` of an integer | none for \|i\| <= 2^24 (exactly representable), else 0.5 + 0.5 | |
//! | `u32(x)`, `i32(x)` of an `f32` | none (truncation towards zero is exact) where every value of x's interval truncates to one integer; else the row is excluded | |
//! | `table[i]`, a constant array at an exact index | none (the stored `f32`; a subnormal entry its own magnitude, for a flush) | |
//!
//! The extra half ULP on every operation pays for the freedom the specification gives an
//! implementation to contract (fuse) and reassociate: one more rounding per operation. A chain
//! of `+` and `-` within a function may be summed in any order: each of its additions is
//! charged in ULP of the sum of its operands' magnitudes, which bounds every partial sum of
//! every order. A chain of `*` within a function may be multiplied in any order: a row where
//! some order would overflow or underflow (the product of all operands above 1 beyond the
//! largest `f32`, or of all below 1 under the smallest normal while the product is normal) is
//! excluded, since an implementation that reorders it promises nothing there; Mesa's lavapipe
//! does reorder `f * (e * n) * pi` into an overflow. Chains are followed within a function only:
//! a reordering across an inlined call is not modelled (a known gap of this bound). Every
//! operation also adds 2^-126 (absolute) where its result may be subnormal, since subnormals
//! may be flushed to zero; a subnormal argument starts with its own magnitude as its error.
//!
//! Range reduction. A value may carry alternatives: `round(u)` or `floor(u)` of a u whose
//! interval [v - e, v + e] straddles a rounding boundary (a half-integer, an integer) is one of
//! the two (or few) integers that interval rounds to, each exact, and the interpreter keeps
//! them all, the form's own value first. Negation, `+`, `-`, `*`, `/` and the builtins act on
//! each alternative in turn, pairing the alternatives of the same `round` or `floor` (so
//! `s = u - n` and the sign `(-1)^n` of one choice of n stay together; alternatives of
//! another source are first taken as their union); any other use (a comparison, a select, a
//! vector's component, the function's result) takes their union: the form's value, with the
//! largest distance of any alternative's interval from it as the error. That union is small
//! exactly where the reduced form is periodic: for `cos(pi u) = (-1)^n cos(pi (u - n))` the
//! choices n and n + 1 at u = n + 1/2 give values within the errors of each other, and the
//! argument pi (u - n) stays in [-pi/2, pi/2] for each, where cos and sin keep their promise.
//! Without the alternatives, the union of u - n over both choices, centred on the form's
//! value 1/2, would span [-1/2, 3/2] and leave [-pi, pi]. Whatever value a conforming
//! implementation computes lies in one alternative's interval, so the bound stays sound.
//!
//! A comparison whose operands lie within their errors of each other may go either way on a
//! GPU: a `select` on it takes the union of both operands' intervals, except inside the
//! helpers of the Beckmann visible-slope solve, whose safeguard branches are taken as the
//! form takes them (an assumption, stated at [`FORM_BRANCHES`]: a known gap of this bound). Where WGSL promises
//! nothing at all (a value beyond the largest finite `f32`, a divisor within its error of 0 or
//! outside [2^-126, 2^126], the logarithm or square root of a value that may be negative), the
//! row is excluded with the reason, listed and counted, not compared.

use naga::{
    BinaryOperator, Block, Expression, Function, Handle, Literal, MathFunction, Module, Statement,
    UnaryOperator,
};

/// f32's smallest normal, 2^-126.
const TINY: f64 = 1.175_494_350_822_287_5e-38;
/// f32's largest finite value.
const MAX32: f64 = 3.402_823_466_385_288_6e38;
/// The name suffix of a helper that is one Newton step x' = S(x; p) = x - f(x; p) / f'(x; p)
/// on its first argument x, the others p its fixed parameters (`brdf_erf_inv_newton`).
///
/// Propagating x's error through S operation by operation charges it twice (once through x,
/// once through the step f / f', which moves with x): the bound would double at each step
/// where Newton in fact squares the error. The rule instead splits the computed result
/// S~(x~) (x~ the iterate the implementation computed, within e of the form's x) as
///
///   S~(x~) - S(x) = [S(x~) - S(x)] + [S~(x~) - S(x~)],
///
/// the exact step's image of x's interval, and the error of evaluating the step at a point
/// (the interpreter's ordinary bound of S's operations with x exact, and p with its errors:
/// the residual's own error over the derivative, the subtraction's rounding). The image is
/// the hull of S at x - e, x and x + e, and at S's fixed point x* where the interval holds
/// it: with f' and f'' of one sign near x*, S(t) - x* = f''(xi) / (2 f'(t)) (t - x*)^2 is
/// monotone on each side of x*, so those points bound it (`bound::tests` samples the
/// interval densely to check it for erf_inv's steps). Where x* lies outside the interval the
/// ends bound a monotone S; where inside, the image is [x*, the larger end] up to its
/// quadratic contraction. The evaluation error is the largest of those at x - e, x and x + e
/// (it is a few ULP of values that barely move over e). x* is taken as S(S(x)), two of the
/// form's own steps in `f64` from x. The rule serves erf^-1's polish (`brdf_erf_inv_newton`)
/// and the Beckmann visible-slope inversion's safeguarded steps (`brdf_beckmann_vndf_newton`,
/// its bracket a parameter): far from the root the interval's image is that of a smooth,
/// monotone map of a tiny interval, near it the quadratic contraction above.
pub const NEWTON_SUFFIX: &str = "_newton";

/// The name prefix of the helpers of a safeguarded root solve (the Beckmann visible-slope
/// inversion: its residual, bracket update and Newton-bisection step) whose comparisons are
/// taken as the form takes them, whatever their operands' errors: the bracket's side, the
/// bisection of an iterate outside the bracket, the fallback where the derivative is not
/// positive. This is an assumption, not a promise of WGSL, and a known gap of this bound:
/// near the root the residual's sign is within its error of 0 and an implementation may move
/// the other end of the bracket, or (its iterate rounding just outside its bracket) bisect
/// where the form takes a Newton step, and end the fixed number of steps at another iterate.
/// On the CPU's f32 such a step and the form's choose alike (the step's direction and the
/// bracket end it replaces follow the same residual), which is why the iterate stays inside
/// its bracket; taking each comparison's two outcomes as independent, as elsewhere, loses that
/// correlation and lets the bound double at each of the seven steps (every row of the
/// Beckmann visible-normal samplers was excluded).
pub const FORM_BRANCHES: &str = "brdf_beckmann_vndf_";

/// The half ULP each operation is charged for a possible contraction or reordering.
const EXTRA: f64 = 0.5;

/// A value and a bound on the distance of the `f32` value computed for it by any conforming
/// implementation: the computed value lies in [v - e, v + e].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Num {
    /// The value of the form, evaluated in `f64` (exact to about 2^-50 relative).
    pub v: f64,
    /// The bound on the error of the `f32` evaluation.
    pub e: f64,
}

impl Num {
    /// `f(a, b)` for a function monotone in both arguments (`min`, `max`): its exact interval
    /// from the operands' intervals (no rounding: WGSL's min and max are exact).
    fn hull(a: Num, b: Num, f: fn(f64, f64) -> f64) -> Num {
        let v = f(a.v, b.v);
        let lo = f(a.v - a.e, b.v - b.e);
        let hi = f(a.v + a.e, b.v + b.e);
        Num {
            v,
            e: (v - lo).max(hi - v),
        }
    }
}

/// A value of the interpreted WGSL.
#[derive(Clone, Debug)]
enum Val {
    Num(Num),
    /// A boolean, and whether every conforming implementation computes the same one.
    Bool {
        v: bool,
        stable: bool,
    },
    Vec(Vec<Num>),
    /// A number that is one of several intervals, one per choice of a `round` or `floor`
    /// (`src` numbers it within a run): `alts[0]` is the form's own value (module docs, "Range
    /// reduction").
    Alt {
        src: u32,
        alts: Vec<Num>,
    },
}

/// The union of alternatives around the first (the form's value): the largest distance of
/// any alternative's interval from it.
fn hull(alts: &[Num]) -> Num {
    let v = alts[0].v;
    let e = alts
        .iter()
        .map(|a| (a.v - v).abs() + a.e)
        .fold(0.0, f64::max);
    Num { v, e }
}

impl Val {
    /// Alternatives as their union; any other value as it is.
    fn collapsed(self) -> Val {
        match self {
            Val::Alt { alts, .. } => Val::Num(hull(&alts)),
            v => v,
        }
    }

    /// A number or the union of alternatives; `None` for a boolean or a vector.
    fn scalar(&self) -> Option<Num> {
        match self {
            Val::Num(n) => Some(*n),
            Val::Alt { alts, .. } => Some(hull(alts)),
            _ => None,
        }
    }
}

/// The ULP of `f32` at magnitude `x` (2^-149 below the normal range).
#[must_use]
pub fn ulp32(x: f64) -> f64 {
    let a = x.abs();
    if a < TINY {
        return f64::from(f32::from_bits(1));
    }
    #[allow(clippy::cast_possible_wrap, clippy::cast_possible_truncation)]
    let exp = ((a.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    f64::powi(2.0, exp - 23)
}

/// `ulps` ULP of a result near `v` (inherited error `e`), plus 2^-126 where it may be
/// subnormal and flushed, plus the `f64` evaluation's own rounding.
fn allow(v: f64, e: f64, ulps: f64) -> f64 {
    let hi = v.abs() + e;
    // An exact zero from exact operands (0 x, x - x) is exact in every rounding mode.
    if hi == 0.0 {
        return 0.0;
    }
    let flush = if v.abs() - e < TINY && hi > 0.0 {
        TINY
    } else {
        0.0
    };
    ulps * ulp32(hi) + flush + hi * f64::powi(2.0, -50)
}

/// Why a row is not compared.
pub type Excluded = &'static str;

/// The interpreter of one module.
pub struct Interp<'m> {
    module: &'m Module,
    /// The first reason the row at hand left WGSL's promises, if it did.
    excluded: Option<Excluded>,
    /// The source number of the next alternatives (`round`, `floor`).
    next_src: u32,
    /// Per function, per expression: whether its value may become part of a longer chain of
    /// sums ([`may_join_a_sum`]), so that a reordering could split it.
    in_sum: Vec<Vec<bool>>,
    /// Per function, per expression: whether its value may become part of a longer chain of
    /// products ([`may_join_a_product`]).
    in_product: Vec<Vec<bool>>,
    /// Calls already run in this row: function and arguments, result and exclusion.
    cache: std::collections::HashMap<Vec<u64>, (Val, Option<Excluded>)>,
}

/// The cache key of a call whose arguments are numbers, booleans or vectors (`None` where
/// one has alternatives, whose source numbering ties them to their row).
fn call_key(h: Handle<Function>, args: &[Val]) -> Option<Vec<u64>> {
    let mut k = vec![h.index() as u64];
    for a in args {
        match a {
            Val::Num(n) => k.extend([1, n.v.to_bits(), n.e.to_bits()]),
            Val::Bool { v, stable } => k.extend([2, u64::from(*v), u64::from(*stable)]),
            Val::Vec(v) => {
                k.extend([3, v.len() as u64]);
                for n in v {
                    k.extend([n.v.to_bits(), n.e.to_bits()]);
                }
            }
            Val::Alt { .. } => return None,
        }
    }
    Some(k)
}

impl<'m> Interp<'m> {
    /// An interpreter of `module`'s functions.
    #[must_use]
    pub fn new(module: &'m Module) -> Self {
        // naga orders a module's functions callees first, so each function's callees are
        // done when it is (a callee not yet done counts as joining every chain).
        let mut in_sum: Vec<Vec<bool>> = Vec::new();
        let mut in_product: Vec<Vec<bool>> = Vec::new();
        for (_, f) in module.functions.iter() {
            let s = may_join_a_sum(f, &in_sum, module);
            let p = may_join_a_product(f, &in_product, module);
            in_sum.push(s);
            in_product.push(p);
        }
        Self {
            module,
            excluded: None,
            next_src: 0,
            in_sum,
            in_product,
            cache: std::collections::HashMap::new(),
        }
    }

    /// Runs the function `name` on `args` (each an `f32`, given as `f64`): its outputs
    /// (components of a vector result in order) with their bounds, or why the row is
    /// excluded.
    ///
    /// # Errors
    /// The reason WGSL promises nothing for this row.
    ///
    /// # Panics
    /// If the module has no function `name`, or the function uses IR this interpreter does
    /// not model (loops, variables, unlisted builtins): the twins are written without them.
    pub fn run(&mut self, name: &str, args: &[f64]) -> Result<Vec<Num>, Excluded> {
        let (h, _) = self
            .module
            .functions
            .iter()
            .find(|(_, f)| f.name.as_deref() == Some(name))
            .unwrap_or_else(|| panic!("no WGSL function {name}"));
        self.excluded = None;
        self.cache.clear();
        let args: Vec<Val> = args
            .iter()
            .map(|&x| {
                // A subnormal argument may be flushed to zero.
                let e = if x != 0.0 && x.abs() < TINY {
                    x.abs()
                } else {
                    0.0
                };
                Val::Num(Num { v: x, e })
            })
            .collect();
        let out = self.call(h, args);
        if let Some(why) = self.excluded {
            return Err(why);
        }
        Ok(match out {
            Val::Num(n) => vec![n],
            Val::Alt { alts, .. } => vec![hull(&alts)],
            Val::Vec(v) => v,
            Val::Bool { .. } => panic!("{name} returns a boolean"),
        })
    }

    /// One application of the Newton-step rule ([`NEWTON_SUFFIX`]) to the function `name`
    /// from the iterate `x` (with its error) and exact parameters: the step's value and bound.
    ///
    /// # Errors
    /// The reason WGSL promises nothing for this step.
    ///
    /// # Panics
    /// If the module has no function `name`.
    pub fn newton_step(&mut self, name: &str, x: Num, params: &[f64]) -> Result<Num, Excluded> {
        let (h, _) = self
            .module
            .functions
            .iter()
            .find(|(_, f)| f.name.as_deref() == Some(name))
            .unwrap_or_else(|| panic!("no WGSL function {name}"));
        self.excluded = None;
        let mut args = vec![Val::Num(x)];
        args.extend(params.iter().map(|&v| Val::Num(Num { v, e: 0.0 })));
        self.cache.clear();
        let out = self.newton(h, args);
        if let Some(why) = self.excluded {
            return Err(why);
        }
        Ok(out.scalar().expect("a number"))
    }

    fn exclude(&mut self, why: Excluded) {
        if self.excluded.is_none() {
            self.excluded = Some(why);
        }
    }

    /// A call: its result, from the cache where the same function ran on the same arguments
    /// within this row (the interpreter is deterministic; the exclusion it met comes with it).
    fn call(&mut self, h: Handle<Function>, args: Vec<Val>) -> Val {
        let key = call_key(h, &args);
        if let Some(k) = &key
            && let Some((v, why)) = self.cache.get(k)
        {
            let (v, why) = (v.clone(), *why);
            if let Some(w) = why {
                self.exclude(w);
            }
            return v;
        }
        let before = self.excluded.take();
        let v = self.run_body(h, args);
        let why = self.excluded;
        if before.is_some() {
            self.excluded = before;
        }
        if let Some(k) = key {
            self.cache.insert(k, (v.clone(), why));
        }
        v
    }

    fn run_body(&mut self, h: Handle<Function>, args: Vec<Val>) -> Val {
        let f = &self.module.functions[h];
        let mut frame = Frame {
            f,
            args,
            memo: vec![None; f.expressions.len()],
            fidx: h.index(),
            form_branches: f
                .name
                .as_deref()
                .is_some_and(|n| n.starts_with(FORM_BRANCHES)),
        };
        self.block(&mut frame, &f.body)
            .unwrap_or_else(|| panic!("{:?} returns nothing", f.name))
    }

    /// One Newton step x' = S(x; p) of a function named `..._newton` (first argument the
    /// iterate x, the others its fixed parameters p, one `f32` result): [`NEWTON_SUFFIX`]'s
    /// rule.
    fn newton(&mut self, h: Handle<Function>, args: Vec<Val>) -> Val {
        let args: Vec<Val> = args.into_iter().map(Val::collapsed).collect();
        let Some(Val::Num(x)) = args.first().cloned() else {
            panic!("a Newton step's first argument is its scalar iterate");
        };
        // S and its evaluation error with the iterate taken as exact at t.
        let at = |s: &mut Self, t: f64| -> Num {
            let mut a = args.clone();
            a[0] = Val::Num(Num { v: t, e: 0.0 });
            s.call(h, a)
                .scalar()
                .unwrap_or_else(|| panic!("a Newton step returns a number"))
        };
        let mid = at(self, x.v);
        let (lo, hi) = if x.e > 0.0 {
            (at(self, x.v - x.e), at(self, x.v + x.e))
        } else {
            (mid, mid)
        };
        // The fixed point of the form's own S (with the parameters' form values): S(x) is one
        // Newton step from x, S(S(x)) another, within f''/(2 f') (S(x) - x*)^2 of it, beyond
        // f64's resolution for the iterates at hand (x within a few f32 ULP of x*).
        let root = if x.e > 0.0 { at(self, mid.v).v } else { mid.v };
        let mut lo_v = lo.v.min(hi.v).min(mid.v);
        let mut hi_v = lo.v.max(hi.v).max(mid.v);
        if (x.v - x.e..=x.v + x.e).contains(&root) {
            lo_v = lo_v.min(root);
            hi_v = hi_v.max(root);
        }
        let image = (mid.v - lo_v).max(hi_v - mid.v);
        let eval = mid.e.max(lo.e).max(hi.e);
        Val::Num(Num {
            v: mid.v,
            e: image + eval,
        })
    }

    fn block(&mut self, fr: &mut Frame<'m>, b: &'m Block) -> Option<Val> {
        for s in b {
            match s {
                Statement::Emit(_) => {}
                Statement::Block(inner) => {
                    if let Some(v) = self.block(fr, inner) {
                        return Some(v);
                    }
                }
                Statement::Call {
                    function,
                    arguments,
                    result,
                } => {
                    let args = arguments.iter().map(|&a| self.expr(fr, a)).collect();
                    let newton = self.module.functions[*function]
                        .name
                        .as_deref()
                        .is_some_and(|n| n.ends_with(NEWTON_SUFFIX));
                    let v = if newton {
                        self.newton(*function, args)
                    } else {
                        self.call(*function, args)
                    };
                    if let Some(r) = result {
                        fr.memo[r.index()] = Some(v);
                    }
                }
                Statement::Return { value } => {
                    return value.map(|v| self.expr(fr, v));
                }
                other => panic!(
                    "{:?}: statement {other:?} is not modelled (the twins use let and select)",
                    fr.f.name
                ),
            }
        }
        None
    }

    fn num(&mut self, fr: &mut Frame<'m>, h: Handle<Expression>) -> Num {
        let v = self.expr(fr, h);
        v.scalar()
            .unwrap_or_else(|| panic!("{:?}: expected a number, found {v:?}", fr.f.name))
    }

    /// `f` on each alternative of the operands (a number taken as it is; the alternatives of
    /// the first source among the operands paired by choice; those of any other source as
    /// their union), or on the numbers themselves where none has alternatives.
    fn lift(&mut self, vals: &[Val], mut f: impl FnMut(&mut Self, &[Num]) -> Num) -> Val {
        let first = vals.iter().find_map(|v| match v {
            Val::Alt { src, alts } => Some((*src, alts.len())),
            _ => None,
        });
        let pick = |v: &Val, j: Option<(u32, usize)>| match (v, j) {
            (Val::Alt { src, alts }, Some((s, j))) if *src == s => alts[j],
            (v, _) => v
                .scalar()
                .unwrap_or_else(|| panic!("{v:?} where a number was expected")),
        };
        let Some((src, n)) = first else {
            let args: Vec<Num> = vals.iter().map(|v| pick(v, None)).collect();
            return Val::Num(f(self, &args));
        };
        let alts = (0..n)
            .map(|j| {
                let args: Vec<Num> = vals.iter().map(|v| pick(v, Some((src, j)))).collect();
                f(self, &args)
            })
            .collect();
        Val::Alt { src, alts }
    }

    /// `round` or `floor` (`f`) of `x`: exact; where x's interval holds the rounding ranges of
    /// up to four integers, each is an alternative (the form's value first); beyond that, their
    /// union.
    fn integer_of(&mut self, x: Val, f: fn(f64) -> f64) -> Val {
        if let Val::Alt { src, alts } = &x
            && alts.iter().all(|a| f(a.v - a.e) == f(a.v + a.e))
        {
            return Val::Alt {
                src: *src,
                alts: alts.iter().map(|a| Num { v: f(a.v), e: 0.0 }).collect(),
            };
        }
        let x = x.scalar().expect("round or floor of a number");
        let (v, lo, hi) = (f(x.v), f(x.v - x.e), f(x.v + x.e));
        if lo == hi {
            return Val::Num(Num { v, e: 0.0 });
        }
        if hi - lo > 3.0 {
            return Val::Num(Num {
                v,
                e: (v - lo).max(hi - v),
            });
        }
        let mut alts = vec![Num { v, e: 0.0 }];
        let mut k = lo;
        while k <= hi {
            if k != v {
                alts.push(Num { v: k, e: 0.0 });
            }
            k += 1.0;
        }
        self.next_src += 1;
        Val::Alt {
            src: self.next_src,
            alts,
        }
    }

    fn literal(l: &Literal) -> Val {
        let n = |v: f64| Val::Num(Num { v, e: 0.0 });
        match *l {
            Literal::F32(x) => n(f64::from(x)),
            #[allow(clippy::cast_possible_truncation)]
            Literal::AbstractFloat(x) | Literal::F64(x) => n(f64::from(x as f32)),
            Literal::U32(x) => n(f64::from(x)),
            Literal::I32(x) => n(f64::from(x)),
            #[allow(clippy::cast_precision_loss)]
            Literal::AbstractInt(x) => n(x as f64),
            Literal::Bool(v) => Val::Bool { v, stable: true },
            ref other => panic!("literal {other:?} is not modelled"),
        }
    }

    fn global(&self, h: Handle<Expression>) -> Val {
        match &self.module.global_expressions[h] {
            Expression::Literal(l) => Self::literal(l),
            Expression::Constant(c) => self.global(self.module.constants[*c].init),
            other => panic!("constant expression {other:?} is not modelled"),
        }
    }

    #[allow(clippy::too_many_lines)]
    fn expr(&mut self, fr: &mut Frame<'m>, h: Handle<Expression>) -> Val {
        if let Some(v) = &fr.memo[h.index()] {
            return v.clone();
        }
        let v = match &fr.f.expressions[h] {
            Expression::Literal(l) => Self::literal(l),
            Expression::Constant(c) => self.global(self.module.constants[*c].init),
            Expression::FunctionArgument(i) => fr.args[*i as usize].clone(),
            Expression::Compose { components, .. } => {
                let mut out = Vec::new();
                for &c in components {
                    match self.expr(fr, c).collapsed() {
                        Val::Num(n) => out.push(n),
                        Val::Vec(v) => out.extend(v),
                        Val::Bool { .. } => panic!("boolean vectors are not modelled"),
                        Val::Alt { .. } => unreachable!("collapsed"),
                    }
                }
                Val::Vec(out)
            }
            Expression::Splat { size, value } => {
                let n = self.num(fr, *value);
                Val::Vec(vec![n; *size as usize])
            }
            Expression::AccessIndex { base, index } => match self.expr(fr, *base) {
                Val::Vec(v) => Val::Num(v[*index as usize]),
                other => panic!("index into {other:?}"),
            },
            Expression::Unary { op, expr } => match (op, self.expr(fr, *expr)) {
                (UnaryOperator::Negate, Val::Num(n)) => Val::Num(neg(n)),
                (UnaryOperator::Negate, Val::Vec(v)) => Val::Vec(v.into_iter().map(neg).collect()),
                (UnaryOperator::Negate, x @ Val::Alt { .. }) => self.lift(&[x], |_, a| neg(a[0])),
                (UnaryOperator::LogicalNot, Val::Bool { v, stable }) => Val::Bool { v: !v, stable },
                (op, x) => panic!("unary {op:?} on {x:?} is not modelled"),
            },
            Expression::Binary { op, left, right } => {
                use BinaryOperator as B;
                let (a, b) = (self.expr(fr, *left), self.expr(fr, *right));
                let scalar = |v: &Val| matches!(v, Val::Num(_) | Val::Alt { .. });
                let alt = |v: &Val| matches!(v, Val::Alt { .. });
                match *op {
                    B::Add | B::Subtract | B::Multiply if self.is_int(fr.f, *left) => {
                        self.lift(&[a, b], |_, xy| int_binary(*op, xy[0], xy[1]))
                    }
                    B::Add | B::Subtract if scalar(&a) && scalar(&b) => {
                        let sub = *op == B::Subtract;
                        let (span, leaves) = self.sum_span(fr, h);
                        // Two operands alone: no reordering can split them.
                        let alone = leaves == 2 && !self.in_sum[fr.fidx][h.index()];
                        self.lift(&[a, b], |_, xy| {
                            let y = if sub { neg(xy[1]) } else { xy[1] };
                            let exact = round32_sum(xy[0].v, y.v)
                                .filter(|&r| r == xy[0].v + y.v)
                                .and_then(|r| exact_result(xy[0], y, r));
                            if alone && let Some(r) = exact {
                                r
                            } else if alone && sum_is_exact(xy[0], y) {
                                add_exact(xy[0], y)
                            } else {
                                add_in(xy[0], y, span)
                            }
                        })
                    }
                    B::Multiply if scalar(&a) && scalar(&b) => {
                        // Two operands alone: no reassociation can split them.
                        let alone = !self.in_product[fr.fidx][h.index()]
                            && Self::product_leaves(fr, h) == 2;
                        let p = self.lift(&[a, b], |_, xy| {
                            if alone && let Some(p) = exact_result(xy[0], xy[1], xy[0].v * xy[1].v)
                            {
                                p
                            } else {
                                mul(xy[0], xy[1])
                            }
                        });
                        let hull = p.scalar().expect("a number");
                        self.check_product_chain(fr, h, hull);
                        p
                    }
                    B::Divide if (alt(&a) || alt(&b)) && scalar(&a) && scalar(&b) => {
                        self.lift(&[a, b], |s, xy| s.div(xy[0], xy[1]))
                    }
                    B::Add | B::Subtract
                        if matches!(a, Val::Vec(_)) || matches!(b, Val::Vec(_)) =>
                    {
                        // Per component, each addition charged in ULP of its component's
                        // chain (a reordering of a vector sum reorders every component).
                        let n = match (&a, &b) {
                            (Val::Vec(x), _) | (_, Val::Vec(x)) => x.len(),
                            _ => unreachable!("one operand is a vector"),
                        };
                        let spans = self.sum_spans(fr, h, n);
                        let comp = |v: &Val, i: usize| match v {
                            Val::Vec(x) => x[i],
                            other => other
                                .scalar()
                                .unwrap_or_else(|| panic!("{other:?} in a vector sum")),
                        };
                        let sub = *op == B::Subtract;
                        Val::Vec(
                            (0..n)
                                .map(|i| {
                                    let y = comp(&b, i);
                                    let y = if sub { neg(y) } else { y };
                                    add_in(comp(&a, i), y, spans[i])
                                })
                                .collect(),
                        )
                    }
                    _ => {
                        let v = self.binary(*op, a.collapsed(), b.collapsed());
                        match v {
                            // A safeguard's comparison takes the form's branch
                            // ([`FORM_BRANCHES`]).
                            Val::Bool { v, .. } if fr.form_branches => {
                                Val::Bool { v, stable: true }
                            }
                            v => v,
                        }
                    }
                }
            }
            Expression::Select {
                condition,
                accept,
                reject,
            } => {
                let Val::Bool { v, stable } = self.expr(fr, *condition) else {
                    panic!("select on a non-boolean")
                };
                // Only the chosen operand's promises matter where the choice is certain.
                let (chosen, other) = if v {
                    (*accept, *reject)
                } else {
                    (*reject, *accept)
                };
                // Vectors select as a whole (a scalar condition): component by component.
                let union = |c: Num, o: Num| Num {
                    v: c.v,
                    e: c.e.max((o.v - c.v).abs() + o.e),
                };
                match (self.expr(fr, chosen).collapsed(), stable) {
                    (c, true) => c,
                    (Val::Num(c), false) => Val::Num(union(c, self.num(fr, other))),
                    (Val::Vec(c), false) => match self.expr(fr, other).collapsed() {
                        Val::Vec(o) => {
                            Val::Vec(c.iter().zip(&o).map(|(&c, &o)| union(c, o)).collect())
                        }
                        x => panic!("select between a vector and {x:?}"),
                    },
                    (x, _) => panic!("select of {x:?} is not modelled"),
                }
            }
            Expression::Math {
                fun,
                arg,
                arg1,
                arg2,
                ..
            } => {
                let x = self.expr(fr, *arg);
                match fun {
                    MathFunction::Round => self.integer_of(x, f64::round_ties_even),
                    MathFunction::Floor => self.integer_of(x, f64::floor),
                    MathFunction::Fract => {
                        // x - floor(x), the one difference alone.
                        let fl = self.integer_of(x.clone(), f64::floor);
                        self.lift(&[x, fl], |_, xf| {
                            let y = neg(xf[1]);
                            if sum_is_exact(xf[0], y) {
                                add_exact(xf[0], y)
                            } else {
                                add_in(xf[0], y, xf[0].v.abs() + xf[0].e + xf[1].v.abs())
                            }
                        })
                    }
                    _ => {
                        let mut vals = vec![x];
                        vals.extend(arg1.map(|a| self.expr(fr, a)));
                        vals.extend(arg2.map(|a| self.expr(fr, a)));
                        let fun = *fun;
                        // fma(2^k, u, c), out of every sum: one rounding of an exact product's
                        // sum ([`fma_pow2`]).
                        let pow2 = match vals[..] {
                            [Val::Num(a), Val::Num(b), Val::Num(c)]
                                if fun == MathFunction::Fma && !self.in_sum[fr.fidx][h.index()] =>
                            {
                                fma_pow2(a, b, c).or_else(|| fma_pow2(b, a, c))
                            }
                            _ => None,
                        };
                        if let Some(n) = pow2 {
                            Val::Num(n)
                        } else {
                            self.lift(&vals, |s, n| {
                                s.math(fun, n[0], n.get(1).copied(), n.get(2).copied())
                            })
                        }
                    }
                }
            }
            Expression::As {
                expr,
                kind,
                convert: Some(_),
            } => {
                let x = self.expr(fr, *expr);
                let from_int = self.is_int(fr.f, *expr);
                self.lift(&[x], |s, n| s.convert(n[0], *kind, from_int))
            }
            Expression::Access { base, index } => {
                let i = self.expr(fr, *index);
                let f = fr.f;
                self.lift(&[i], |s, n| s.table_entry(f, *base, n[0]))
            }
            other => panic!("{:?}: expression {other:?} is not modelled", fr.f.name),
        };
        // NaN fails the comparison too.
        let fits = |n: &Num| n.v.abs() + n.e <= MAX32;
        if let Some(n) = v.scalar()
            && !fits(&n)
        {
            self.exclude("a value may exceed the largest finite f32 (or is NaN)");
        }
        fr.memo[h.index()] = Some(v.clone());
        v
    }

    fn binary(&mut self, op: BinaryOperator, a: Val, b: Val) -> Val {
        use BinaryOperator as B;
        match (a, b) {
            (Val::Num(a), Val::Num(b)) => match op {
                B::Add => Val::Num(add(a, b)),
                B::Subtract => Val::Num(add(a, Num { v: -b.v, e: b.e })),
                B::Multiply => Val::Num(mul(a, b)),
                B::Divide => Val::Num(self.div(a, b)),
                B::Less | B::LessEqual | B::Greater | B::GreaterEqual | B::Equal | B::NotEqual => {
                    let v = match op {
                        B::Less => a.v < b.v,
                        B::LessEqual => a.v <= b.v,
                        B::Greater => a.v > b.v,
                        B::GreaterEqual => a.v >= b.v,
                        B::Equal => a.v == b.v,
                        _ => a.v != b.v,
                    };
                    // Certain where the intervals cannot touch (or both values are exact).
                    let gap = (a.v - b.v).abs();
                    let err = a.e + b.e;
                    Val::Bool {
                        v,
                        stable: err == 0.0 || gap > err,
                    }
                }
                other => panic!("binary {other:?} on numbers is not modelled"),
            },
            (Val::Bool { v: x, stable: sx }, Val::Bool { v: y, stable: sy }) => match op {
                // Certain where both are, or where one certain operand decides alone.
                B::LogicalAnd | B::And => {
                    let decided = [(sx, x), (sy, y)].contains(&(true, false));
                    Val::Bool {
                        v: x && y,
                        stable: (sx && sy) || decided,
                    }
                }
                B::LogicalOr | B::InclusiveOr => {
                    let decided = [(sx, x), (sy, y)].contains(&(true, true));
                    Val::Bool {
                        v: x || y,
                        stable: (sx && sy) || decided,
                    }
                }
                other => panic!("binary {other:?} on booleans is not modelled"),
            },
            (Val::Vec(a), Val::Vec(b)) => Val::Vec(
                a.iter()
                    .zip(&b)
                    .map(|(&x, &y)| match self.binary(op, Val::Num(x), Val::Num(y)) {
                        Val::Num(n) => n,
                        _ => panic!("vector comparison is not modelled"),
                    })
                    .collect(),
            ),
            (Val::Vec(a), Val::Num(s)) | (Val::Num(s), Val::Vec(a)) => Val::Vec(
                a.iter()
                    .map(|&x| match self.binary(op, Val::Num(x), Val::Num(s)) {
                        Val::Num(n) => n,
                        _ => panic!("vector comparison is not modelled"),
                    })
                    .collect(),
            ),
            (a, b) => panic!("binary {op:?} on {a:?} and {b:?} is not modelled"),
        }
    }

    /// The leaves of the chain of `+` and `-` (or of `*`) that `h` heads, within its function:
    /// the operands an implementation may reorder.
    fn chain_leaves(
        fr: &Frame<'m>,
        h: Handle<Expression>,
        products: bool,
        out: &mut Vec<Handle<Expression>>,
    ) {
        use BinaryOperator as B;
        match &fr.f.expressions[h] {
            Expression::Binary {
                op: B::Multiply,
                left,
                right,
            } if products => {
                Self::chain_leaves(fr, *left, products, out);
                Self::chain_leaves(fr, *right, products, out);
            }
            Expression::Binary {
                op: B::Add | B::Subtract,
                left,
                right,
            } if !products => {
                Self::chain_leaves(fr, *left, products, out);
                Self::chain_leaves(fr, *right, products, out);
            }
            _ => out.push(h),
        }
    }

    /// The number of leaves of the chain of products `h` heads.
    fn product_leaves(fr: &Frame<'m>, h: Handle<Expression>) -> usize {
        let mut leaves = Vec::new();
        Self::chain_leaves(fr, h, true, &mut leaves);
        leaves.len()
    }

    /// The sum of the magnitudes (with their errors) of the leaves of the sum `h` heads: no
    /// partial sum of any reordering of the chain exceeds it, so each addition's rounding is
    /// charged in ULP of it.
    fn sum_span(&mut self, fr: &mut Frame<'m>, h: Handle<Expression>) -> (f64, usize) {
        let mut leaves = Vec::new();
        Self::chain_leaves(fr, h, false, &mut leaves);
        let n = leaves.len();
        let span = leaves
            .into_iter()
            .map(|l| self.expr(fr, l).scalar().map_or(0.0, |n| n.v.abs() + n.e))
            .sum();
        (span, n)
    }

    /// [`Self::sum_span`] per component of a vector sum of `n` components (a scalar leaf, a
    /// splatted operand, counts in every component).
    fn sum_spans(&mut self, fr: &mut Frame<'m>, h: Handle<Expression>, n: usize) -> Vec<f64> {
        let mut leaves = Vec::new();
        Self::chain_leaves(fr, h, false, &mut leaves);
        let mut span = vec![0.0; n];
        for l in leaves {
            match self.expr(fr, l) {
                Val::Vec(v) => {
                    for (s, x) in span.iter_mut().zip(&v) {
                        *s += x.v.abs() + x.e;
                    }
                }
                other => {
                    if let Some(x) = other.scalar() {
                        span.iter_mut().for_each(|s| *s += x.v.abs() + x.e);
                    }
                }
            }
        }
        span
    }

    /// Excludes the row where some reordering of the chain of products `h` heads (whose
    /// value is `p`) would overflow (the largest partial product: all leaves above 1), or
    /// underflow (the smallest: all leaves below 1) while `p` is certainly a normal number.
    /// Where `p` may be 0 or subnormal, a partial product flushed to 0 stays within its
    /// bound.
    fn check_product_chain(&mut self, fr: &mut Frame<'m>, h: Handle<Expression>, p: Num) {
        let mut leaves = Vec::new();
        Self::chain_leaves(fr, h, true, &mut leaves);
        let (mut big, mut small) = (1.0f64, 1.0f64);
        for l in leaves {
            // The magnitudes every alternative allows (their union may straddle 0 where
            // none does: a sign +-1).
            let alts = match self.expr(fr, l) {
                Val::Num(n) => vec![n],
                Val::Alt { alts, .. } => alts,
                _ => Vec::new(),
            };
            if !alts.is_empty() {
                let lo = alts
                    .iter()
                    .map(|n| (n.v.abs() - n.e).max(0.0))
                    .fold(f64::INFINITY, f64::min);
                let hi = alts.iter().map(|n| n.v.abs() + n.e).fold(0.0, f64::max);
                big *= hi.max(1.0);
                small *= lo.min(1.0);
            }
        }
        if big > MAX32 {
            self.exclude("a reordered product may overflow");
        } else if small < TINY && p.v.abs() - p.e >= TINY {
            self.exclude("a reordered product may underflow");
        }
    }

    /// Whether `h` is integer-typed (`u32`, `i32`): an integer literal or constant, a
    /// conversion to an integer, an integer argument, or arithmetic, `min`, `max`, `clamp`,
    /// `abs` or a `select` of such (WGSL's operands share their type, so the first tells).
    fn is_int(&self, f: &Function, h: Handle<Expression>) -> bool {
        use naga::ScalarKind as K;
        let int = |ty: Handle<naga::Type>| {
            matches!(&self.module.types[ty].inner,
                naga::TypeInner::Scalar(s) if matches!(s.kind, K::Uint | K::Sint))
        };
        match &f.expressions[h] {
            Expression::Literal(l) => matches!(
                l,
                Literal::U32(_) | Literal::I32(_) | Literal::AbstractInt(_)
            ),
            Expression::As { kind, .. } => matches!(kind, K::Uint | K::Sint),
            Expression::FunctionArgument(i) => int(f.arguments[*i as usize].ty),
            Expression::Constant(c) => int(self.module.constants[*c].ty),
            Expression::Binary { left, .. } => self.is_int(f, *left),
            Expression::Math {
                fun: MathFunction::Min | MathFunction::Max | MathFunction::Clamp | MathFunction::Abs,
                arg,
                ..
            } => self.is_int(f, *arg),
            Expression::Select { accept, .. } => self.is_int(f, *accept),
            _ => false,
        }
    }

    /// The numeric conversion of `x` to `kind` (WGSL, "Conversion Built-in Functions"): an
    /// integer to `f32` is exact below 2^24 (the twins' indices), else rounded to a
    /// neighbour; an `f32` to an integer truncates towards zero (saturating, `u32` at 0), exact
    /// where every value of x's interval truncates to the same integer; where they do not,
    /// the row is excluded (a GPU may land on either integer, and an index on either entry).
    fn convert(&mut self, x: Num, kind: naga::ScalarKind, from_int: bool) -> Num {
        use naga::ScalarKind as K;
        match kind {
            K::Float if from_int => Num {
                v: x.v,
                e: x.e
                    + if x.v.abs() <= f64::powi(2.0, 24) {
                        0.0
                    } else {
                        allow(x.v, 0.0, 0.5 + EXTRA)
                    },
            },
            K::Uint | K::Sint if from_int => x,
            K::Uint | K::Sint => {
                let t = |y: f64| {
                    let t = y.trunc();
                    if kind == K::Uint { t.max(0.0) } else { t }
                };
                if t(x.v - x.e) != t(x.v + x.e) {
                    self.exclude("a conversion to an integer may truncate to either neighbour");
                }
                Num { v: t(x.v), e: 0.0 }
            }
            other => panic!("conversion to {other:?} is not modelled"),
        }
    }

    /// Entry `i` (an exact integer) of the constant array `base` (a table the twin reads,
    /// such as the sheen albedo texture): the stored `f32` exactly, or within its own
    /// magnitude where it is subnormal (it may be flushed to 0). An index outside the array
    /// is excluded.
    fn table_entry(&mut self, f: &Function, base: Handle<Expression>, i: Num) -> Num {
        let Expression::Constant(c) = f.expressions[base] else {
            panic!("{:?}: indexing a non-constant is not modelled", f.name)
        };
        let Expression::Compose { components, .. } =
            &self.module.global_expressions[self.module.constants[c].init]
        else {
            panic!("{:?}: the indexed constant is not an array", f.name)
        };
        assert!(i.e == 0.0, "{:?}: an index with an error bound", f.name);
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let Some(&entry) = components.get(i.v as usize).filter(|_| i.v >= 0.0) else {
            self.exclude("an index may leave its array");
            return Num { v: 0.0, e: 0.0 };
        };
        let v = self.global(entry).scalar().expect("a table of numbers");
        Num {
            v: v.v,
            e: if v.v != 0.0 && v.v.abs() < TINY {
                v.v.abs()
            } else {
                0.0
            },
        }
    }

    fn div(&mut self, a: Num, b: Num) -> Num {
        let m = b.v.abs();
        if m <= b.e {
            self.exclude("a divisor may be 0");
            return Num {
                v: a.v / b.v,
                e: 0.0,
            };
        }
        if m - b.e < TINY || m + b.e > f64::powi(2.0, 126) {
            self.exclude("a divisor may leave [2^-126, 2^126], where x / y has no accuracy");
        }
        let v = a.v / b.v;
        let e = (a.v.abs() * b.e + m * a.e) / (m * (m - b.e));
        Num {
            v,
            e: e + allow(v, e, 2.5 + EXTRA),
        }
    }

    #[allow(clippy::many_single_char_names)]
    fn math(&mut self, fun: MathFunction, x: Num, y: Option<Num>, z: Option<Num>) -> Num {
        use MathFunction as M;
        let y2 = || y.expect("a second argument");
        match fun {
            M::Abs => Num {
                v: x.v.abs(),
                e: x.e,
            },
            M::Min => Num::hull(x, y2(), f64::min),
            M::Max => Num::hull(x, y2(), f64::max),
            M::Clamp => {
                let (lo, hi) = (y2(), z.expect("clamp's high end"));
                Num::hull(Num::hull(x, lo, f64::max), hi, f64::min)
            }
            M::Saturate => {
                let (zero, one) = (Num { v: 0.0, e: 0.0 }, Num { v: 1.0, e: 0.0 });
                Num::hull(Num::hull(x, zero, f64::max), one, f64::min)
            }
            M::Fma => add(mul(x, y2()), z.expect("fma's addend")),
            M::Sqrt => self.sqrt(x),
            M::InverseSqrt => {
                if x.v - x.e <= 0.0 {
                    self.exclude("inverseSqrt of a value that may be <= 0");
                    return Num { v: 0.0, e: 0.0 };
                }
                self.monotone(x, |t| 1.0 / t.sqrt(), 2.0 + EXTRA)
            }
            M::Exp | M::Exp2 => {
                let f = if fun == M::Exp { f64::exp } else { f64::exp2 };
                let big = x.v.abs() + x.e;
                self.monotone(x, f, 3.0 + 2.0 * big + EXTRA)
            }
            M::Log | M::Log2 => {
                let f = if fun == M::Log { f64::ln } else { f64::log2 };
                self.log(x, f)
            }
            M::Pow => {
                // Inherited from exp2(y * log2(x)).
                let l = self.log(x, f64::log2);
                let p = mul(y2(), l);
                let big = p.v.abs() + p.e;
                self.monotone(p, f64::exp2, 3.0 + 2.0 * big + EXTRA)
            }
            M::Sin | M::Cos => {
                // Absolute 2^-11 inside [-pi, pi], nothing promised outside; both are
                // 1-Lipschitz, so the argument's error passes through at most unchanged.
                if x.v.abs() + x.e > std::f64::consts::PI {
                    self.exclude("sin or cos of an argument that may leave [-pi, pi]");
                }
                let v = if fun == M::Sin { x.v.sin() } else { x.v.cos() };
                Num {
                    v,
                    e: x.e + f64::powi(2.0, -11) + allow(v, x.e, EXTRA),
                }
            }
            M::Asin => self.asin(x),
            M::Acos => self.acos(x),
            other => panic!("builtin {other:?} is not modelled"),
        }
    }

    /// A monotone function of x: the inherited error from the interval's ends, plus its own
    /// allowance in ULP.
    fn monotone(&mut self, x: Num, f: impl Fn(f64) -> f64, ulps: f64) -> Num {
        let v = f(x.v);
        let (a, b) = (f(x.v - x.e), f(x.v + x.e));
        let e = (a - v).abs().max((b - v).abs());
        if !e.is_finite() {
            self.exclude("a builtin's argument interval leaves its domain");
        }
        Num {
            v,
            e: e + allow(v, e, ulps),
        }
    }

    fn log(&mut self, x: Num, f: fn(f64) -> f64) -> Num {
        if x.v - x.e <= 0.0 {
            self.exclude("log of a value that may be <= 0");
            return Num { v: 0.0, e: 0.0 };
        }
        let inside = x.v - x.e <= 2.0 && x.v + x.e >= 0.5;
        let outside = x.v - x.e < 0.5 || x.v + x.e > 2.0;
        let r = self.monotone(x, f, if outside { 3.0 + EXTRA } else { 0.0 });
        let abs = if inside { f64::powi(2.0, -21) } else { 0.0 };
        Num {
            v: r.v,
            e: r.e + abs,
        }
    }

    /// asin(x), inherited from `atan2(x, sqrt(1.0 - x * x))`: the product, the difference and
    /// the square root as above, then atan2's own 4096 ULP over the interval its arguments'
    /// errors span (atan2(y, s) is monotone in each argument for s >= 0: its corners bound
    /// it).
    fn asin(&mut self, x: Num) -> Num {
        if x.v.abs() > 1.0 {
            self.exclude("asin of a value outside [-1, 1]");
            return Num { v: 0.0, e: 0.0 };
        }
        let one = Num { v: 1.0, e: 0.0 };
        let d = add(one, neg(mul(x, x)));
        let s = self.sqrt(d);
        let v = x.v.asin();
        let s_lo = (s.v - s.e).max(0.0);
        let mut e: f64 = 0.0;
        for y in [x.v - x.e, x.v + x.e] {
            for t in [s_lo, s.v + s.e] {
                e = e.max((y.atan2(t) - v).abs());
            }
        }
        Num {
            v,
            e: e + allow(v, e, 4096.0 + EXTRA),
        }
    }

    /// acos(x), inherited from `atan2(sqrt(1.0 - x * x), x)`: as [`Self::asin`] with the
    /// arguments of atan2 swapped (atan2(s, x) for s >= 0 is monotone in each argument).
    fn acos(&mut self, x: Num) -> Num {
        if x.v.abs() > 1.0 {
            self.exclude("acos of a value outside [-1, 1]");
            return Num { v: 0.0, e: 0.0 };
        }
        let one = Num { v: 1.0, e: 0.0 };
        let d = add(one, neg(mul(x, x)));
        let s = self.sqrt(d);
        let v = x.v.acos();
        let s_lo = (s.v - s.e).max(0.0);
        let mut e: f64 = 0.0;
        for t in [s_lo, s.v + s.e] {
            for y in [x.v - x.e, x.v + x.e] {
                e = e.max((t.atan2(y) - v).abs());
            }
        }
        Num {
            v,
            e: e + allow(v, e, 4096.0 + EXTRA),
        }
    }

    /// sqrt(x) as 1 / inverseSqrt(x): 2 ULP on the inverse root is a relative 2^-22, which
    /// the reciprocal keeps, at most 4 ULP of the root; then the division's 2.5 ULP and the
    /// extra half. At x = 0 the result's interval is [0, its ULP allowance].
    fn sqrt(&mut self, x: Num) -> Num {
        if x.v < 0.0 {
            self.exclude("sqrt of a negative value");
            return Num { v: 0.0, e: 0.0 };
        }
        let v = x.v.sqrt();
        let lo = (x.v - x.e).max(0.0).sqrt();
        let hi = (x.v + x.e).sqrt();
        let e = (v - lo).max(hi - v);
        Num {
            v,
            e: e + allow(v, e, 4.0 + 2.5 + EXTRA),
        }
    }
}

/// The interpreter's state in one call.
struct Frame<'m> {
    f: &'m Function,
    args: Vec<Val>,
    memo: Vec<Option<Val>>,
    /// The function's index in the module (for [`Interp`]'s `in_sum`).
    fidx: usize,
    /// Whether its comparisons take the form's branch ([`FORM_BRANCHES`]).
    form_branches: bool,
}

/// Per expression of `f`: whether its value may become part of a longer sum an implementation
/// could reorder. Only a value whose every use is an operand of `*` or `/`, a comparison, a
/// condition or a builtin's argument (but `fma`'s addend) is kept out of every sum; any other
/// use (an operand of `+` or `-`, `fma`'s addend, a negation, a vector's component, a select's
/// value, a stored, passed or returned value (but to a Newton step's parameter that joins no
/// chain there), a conversion) may carry it into one, across
/// an inlined call too, and so does not let a difference count as exact.
fn may_join_a_sum(f: &Function, done: &[Vec<bool>], module: &Module) -> Vec<bool> {
    use BinaryOperator as B;
    let mut flag = vec![false; f.expressions.len()];
    for (_, e) in f.expressions.iter() {
        let mut mark = |h: &Handle<Expression>| flag[h.index()] = true;
        match e {
            Expression::Binary {
                op:
                    B::Multiply
                    | B::Divide
                    | B::Less
                    | B::LessEqual
                    | B::Greater
                    | B::GreaterEqual
                    | B::Equal
                    | B::NotEqual,
                ..
            } => {}
            Expression::Binary { left, right, .. } => {
                mark(left);
                mark(right);
            }
            Expression::Math {
                fun: MathFunction::Fma,
                arg2: Some(c),
                ..
            } => mark(c),
            Expression::Math { .. } => {}
            Expression::Select { accept, reject, .. } => {
                mark(accept);
                mark(reject);
            }
            Expression::Compose { components, .. } => components.iter().for_each(&mut mark),
            Expression::Unary { expr, .. } | Expression::As { expr, .. } => mark(expr),
            Expression::AccessIndex { base, .. } | Expression::Access { base, .. } => mark(base),
            Expression::Splat { value, .. } => mark(value),
            Expression::Swizzle { vector, .. } => mark(vector),
            _ => {}
        }
    }
    mark_statement_uses(&f.body, &mut flag, done, module);
    flag
}

/// Per expression of `f`: whether its value may become part of a longer chain of products an
/// implementation could reassociate: an operand of `*`, or any use that may carry it into one
/// (as [`may_join_a_sum`]: a negation, a vector's component, a select's value, a stored,
/// passed or returned value, a conversion). An operand of `+`, `-`, `/`, a comparison or a
/// builtin's argument is not.
fn may_join_a_product(f: &Function, done: &[Vec<bool>], module: &Module) -> Vec<bool> {
    use BinaryOperator as B;
    let mut flag = vec![false; f.expressions.len()];
    for (_, e) in f.expressions.iter() {
        let mut mark = |h: &Handle<Expression>| flag[h.index()] = true;
        match e {
            Expression::Binary {
                op: B::Multiply,
                left,
                right,
            } => {
                mark(left);
                mark(right);
            }
            Expression::Select { accept, reject, .. } => {
                mark(accept);
                mark(reject);
            }
            Expression::Compose { components, .. } => components.iter().for_each(&mut mark),
            Expression::Unary { expr, .. } | Expression::As { expr, .. } => mark(expr),
            Expression::AccessIndex { base, .. } | Expression::Access { base, .. } => mark(base),
            Expression::Splat { value, .. } => mark(value),
            Expression::Swizzle { vector, .. } => mark(vector),
            _ => {}
        }
    }
    mark_statement_uses(&f.body, &mut flag, done, module);
    flag
}

/// [`may_join_a_sum`]'s walk of the statements: stored and returned values, and values passed
/// to a function, except to a Newton step ([`NEWTON_SUFFIX`]) whose parameter joins no chain
/// there (by `done`, the callees' flags; a callee not in `done` counts as joining).
fn mark_statement_uses(block: &Block, flag: &mut [bool], done: &[Vec<bool>], module: &Module) {
    for st in block.iter() {
        match st {
            Statement::Store { value, .. } => flag[value.index()] = true,
            Statement::Return { value: Some(v) } => flag[v.index()] = true,
            Statement::Call {
                function,
                arguments,
                ..
            } => {
                let callee = &module.functions[*function];
                for (i, a) in arguments.iter().enumerate() {
                    // Followed into Newton steps only (erf^-1's q = 1 - |y|, a divisor
                    // there): followed everywhere, the exact differences it finds tighten
                    // diffuse::BurleyRenormalized::eval's bound below the distance between
                    // its form (0) and the Rust kernel (2.4e-38) at a cosine of 2^-126.
                    let newton = callee
                        .name
                        .as_deref()
                        .is_some_and(|n| n.ends_with(NEWTON_SUFFIX));
                    let joins = !newton
                        || done.get(function.index()).is_none_or(|cf| {
                            callee.expressions.iter().any(|(h, e)| {
                                matches!(e, Expression::FunctionArgument(j) if *j as usize == i)
                                    && cf[h.index()]
                            })
                        });
                    if joins {
                        flag[a.index()] = true;
                    }
                }
            }
            Statement::Block(b) => mark_statement_uses(b, flag, done, module),
            Statement::If { accept, reject, .. } => {
                mark_statement_uses(accept, flag, done, module);
                mark_statement_uses(reject, flag, done, module);
            }
            Statement::Loop {
                body, continuing, ..
            } => {
                mark_statement_uses(body, flag, done, module);
                mark_statement_uses(continuing, flag, done, module);
            }
            Statement::Switch { cases, .. } => {
                for c in cases {
                    mark_statement_uses(&c.body, flag, done, module);
                }
            }
            _ => {}
        }
    }
}

/// `a op b` on integers (`+`, `-`, `*`): exact, as WGSL's integer arithmetic is where it does
/// not wrap (the twins' table indices stay far below 2^31).
fn int_binary(op: BinaryOperator, a: Num, b: Num) -> Num {
    assert!(
        a.e == 0.0 && b.e == 0.0,
        "integer operands with an error bound"
    );
    let v = match op {
        BinaryOperator::Add => a.v + b.v,
        BinaryOperator::Subtract => a.v - b.v,
        _ => a.v * b.v,
    };
    assert!(
        v.abs() < f64::powi(2.0, 31),
        "integer arithmetic that may wrap"
    );
    Num { v, e: 0.0 }
}

fn add(a: Num, b: Num) -> Num {
    add_in(a, b, 0.0)
}

/// a + b, its rounding charged in ULP of the larger of the result and `span` (the magnitude
/// of the sum's chain, which bounds every partial sum of a reordering).
fn add_in(a: Num, b: Num, span: f64) -> Num {
    let v = a.v + b.v;
    let e = a.e + b.e;
    let own = allow(v, e, 0.5 + EXTRA);
    let reordered = (0.5 + EXTRA) * ulp32(span);
    Num {
        v,
        e: e + own.max(reordered),
    }
}

/// Whether a + b is exact for every pair of `f32` in the operands' intervals: one operand is
/// exactly 0, or (Sterbenz's lemma) a + b = p - q with p, q of one sign and q / 2 <= p <= 2 q
/// throughout.
fn sum_is_exact(a: Num, b: Num) -> bool {
    let zero = |n: Num| n.v == 0.0 && n.e == 0.0;
    if zero(a) || zero(b) {
        return true;
    }
    let (p, q) = if a.v < 0.0 { (neg(a), b) } else { (a, neg(b)) };
    let (p_lo, p_hi, q_lo, q_hi) = (p.v - p.e, p.v + p.e, q.v - q.e, q.v + q.e);
    p_lo > 0.0 && q_lo > 0.0 && q_hi <= 2.0 * p_lo && p_hi <= 2.0 * q_lo
}

/// a + b where [`sum_is_exact`]: the inherited errors, and half an ULP of the result for a
/// contraction of an operand's product into an `fma` (which rounds once), unless both operands
/// are exact (their product, fused or not, is then the exact value too).
fn add_exact(a: Num, b: Num) -> Num {
    let v = a.v + b.v;
    let e = a.e + b.e;
    // Exact operands: the sum is exact in f64 too (Sterbenz holds in any binary format).
    let own = if e == 0.0 {
        flush(v, e)
    } else {
        allow(v, e, EXTRA)
    };
    Num { v, e: e + own }
}

/// 2^-126 where a result near `v` (inherited error `e`) may be subnormal and flushed to 0.
fn flush(v: f64, e: f64) -> f64 {
    if v.abs() - e < TINY && v.abs() + e > 0.0 {
        TINY
    } else {
        0.0
    }
}

fn neg(a: Num) -> Num {
    Num { v: -a.v, e: a.e }
}

/// Whether `n` is exactly a power of two (an exact operand whose product is exact).
fn power_of_two(n: Num) -> bool {
    let m = n.v.abs();
    // Normal as an f32 (a subnormal literal may be flushed to 0).
    n.e == 0.0 && m >= TINY && m.is_normal() && m.to_bits() & ((1u64 << 52) - 1) == 0
}

/// The exact result `r` (evaluated exactly in `f64`) of an operation on the exact operands `a`
/// and `b`, where it is a normal `f32` (or 0): then every rounding mode, fused or not, returns
/// it, so it carries no error. `None` otherwise.
fn exact_result(a: Num, b: Num, r: f64) -> Option<Num> {
    #[allow(clippy::cast_possible_truncation)]
    let representable = f64::from(r as f32) == r && (r == 0.0 || r.abs() >= TINY);
    (a.e == 0.0 && b.e == 0.0 && representable).then_some(Num { v: r, e: 0.0 })
}

/// The `f32` nearest the exact sum p + c of two `f64` (ties to even), or `None` where the
/// `f64` sum rounds onto an `f32` midpoint (then the exact sum's side of it is not known here).
/// Rounding to nearest is monotone and `f32` midpoints are `f64` numbers, so the `f64` sum
/// lies on the exact sum's side of every midpoint it does not hit.
fn round32_sum(p: f64, c: f64) -> Option<f64> {
    let s = p + c;
    let bb = s - p;
    let err = (p - (s - bb)) + (c - bb);
    #[allow(clippy::cast_possible_truncation)]
    let r = f64::from(s as f32);
    let tie = (s - r).abs() == 0.5 * ulp32(r.abs().min(s.abs()).max(TINY));
    (err == 0.0 || !tie).then_some(r)
}

/// fma(k, u, c) with k an exact power of two and c exact: the product k u is exact (in `f64`
/// too) for every u in its interval, so whether the implementation fuses or not the result is
/// one rounding of k u + c, monotone in u: it lies between the roundings at the interval's
/// ends. Where both ends round to the form's own `f32` value, that is exact: `2 u - 1` for u
/// in [1/4, 1) by Sterbenz's lemma, wherever 2 u is a multiple of the result's ULP, and for a
/// subnormal u (flushed or not, 2 u - 1 rounds to -1), so that `brdf_cos_sin_2pi`'s
/// t = (2 u - 1) pi' keeps |t| <= pi' at u = 0 and u = 1 - 2^-24, where a charged rounding
/// would push it past pi. Elsewhere the charge is the distance to the farther end's rounding
/// (at most one ULP). `None` where the rule does not apply: an unfused k u may be subnormal
/// (and flushed) at a normal u, or an end's sum lands on an `f32` midpoint. The caller checks
/// that the value joins no longer sum that a reassociation could split.
fn fma_pow2(k: Num, u: Num, c: Num) -> Option<Num> {
    let (lo_u, hi_u) = (u.v - u.e, u.v + u.e);
    let flushable = |t: f64| {
        let p = (k.v * t).abs();
        p != 0.0 && p < TINY
    };
    if !power_of_two(k) || c.e != 0.0 || ((flushable(lo_u) || flushable(hi_u)) && lo_u > 0.0) {
        return None;
    }
    let lo = round32_sum(k.v * lo_u, c.v)?;
    let hi = round32_sum(k.v * hi_u, c.v)?;
    let v = k.v * u.v + c.v;
    let e = (lo - v).abs().max((hi - v).abs());
    Some(Num {
        v,
        e: e + flush(v, e),
    })
}

fn mul(a: Num, b: Num) -> Num {
    let v = a.v * b.v;
    let e = a.v.abs() * b.e + b.v.abs() * a.e + a.e * b.e;
    // A product by 2^k is exact (in f64 too) but where it is subnormal.
    let own = if power_of_two(a) || power_of_two(b) {
        flush(v, e)
    } else {
        allow(v, e, 0.5 + EXTRA)
    };
    Num { v, e: e + own }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn module(src: &str) -> Module {
        naga::front::wgsl::parse_str(src).expect("parses")
    }

    #[test]
    fn a_sum_of_exact_values_is_allowed_one_ulp() {
        let m = module("fn f(a: f32, b: f32) -> f32 { return a + b; }");
        let r = Interp::new(&m).run("f", &[1.0, 2.0]).unwrap();
        assert_eq!(r[0].v, 3.0);
        // 0.5 for the rounding, 0.5 for a contraction: 1 ULP of 3 = 2^-22.
        assert!((r[0].e - f64::powi(2.0, -22)).abs() < 1e-12, "{}", r[0].e);
    }

    /// A 2 x 2 table indexed as wgsl/layers.wgsl indexes the sheen albedo.
    const TABLE: &str = "const T: array<f32, 4> = array<f32, 4>(1.0, 2.5, 3.25, 1e-40);
    fn f(x: f32, y: f32) -> vec3<f32> {
        let j = min(u32(x), 0u);
        let i = min(u32(y), 1u);
        let row = i * 2u + j;
        return vec3<f32>(f32(row), T[row], T[row + 1u]);
    }";

    #[test]
    fn a_table_entry_at_an_integer_index_is_exact() {
        let m = module(TABLE);
        let mut i = Interp::new(&m);
        let r = i.run("f", &[0.5, 1.25]).unwrap();
        // row = 2 exactly (integer arithmetic charged as f32 would leave the index inexact,
        // and the lookup would panic), T[2] = 3.25 exactly, T[3] subnormal: its magnitude
        // for a flush to 0.
        assert_eq!((r[0].v, r[0].e), (2.0, 0.0));
        assert_eq!((r[1].v, r[1].e), (3.25, 0.0));
        let tiny = f64::from(1e-40f32);
        assert_eq!((r[2].v, r[2].e), (tiny, tiny));
        // y = 7 clamps to row 1 by the min; an index past the end is excluded, not read.
        assert_eq!(i.run("f", &[0.5, 7.0]).unwrap()[1].v, 3.25);
        let past = module(
            "const T: array<f32, 2> = array<f32, 2>(1.0, 2.0);
            fn f(x: f32) -> f32 { return T[u32(x)]; }",
        );
        let mut i = Interp::new(&past);
        assert_eq!(i.run("f", &[1.5]).unwrap()[0].v, 2.0);
        assert!(i.run("f", &[2.5]).is_err());
    }

    #[test]
    fn a_conversion_that_may_truncate_either_way_is_excluded() {
        let m = module("fn f(a: f32) -> f32 { return f32(u32(a * 3.0)); }");
        let mut i = Interp::new(&m);
        // 3 (1/3 in f32) is 1 within a rounding: u32 of it may be 0 or 1.
        assert!(i.run("f", &[f64::from(1.0f32 / 3.0)]).is_err());
        let r = i
            .run("f", &[0.5])
            .expect("1.5 truncates to 1 whatever its rounding");
        assert_eq!((r[0].v, r[0].e), (1.0, 0.0));
    }

    #[test]
    fn integer_arithmetic_is_exact() {
        let m = module("fn f(x: f32) -> f32 { let i = u32(x); return f32(i * 16u + 3u); }");
        let r = Interp::new(&m).run("f", &[2.5]).unwrap();
        assert_eq!((r[0].v, r[0].e), (35.0, 0.0));
    }

    #[test]
    fn a_division_by_a_value_near_zero_is_excluded() {
        let m = module("fn f(a: f32, b: f32) -> f32 { return a / (b - 1.0); }");
        let mut i = Interp::new(&m);
        assert!(i.run("f", &[1.0, 1.0]).is_err());
        assert!(i.run("f", &[1.0, 2.0]).is_ok());
    }

    #[test]
    fn an_uncertain_select_takes_both_operands() {
        // b 0.1 10 - 1 at b = 1 is 0 in exact arithmetic, give or take a few ULP: either branch.
        let m = module(
            "fn f(b: f32) -> f32 { return select(0.0, 10.0, (b * 0.1) * 10.0 - 1.0 >= 0.0); }",
        );
        let r = Interp::new(&m).run("f", &[1.0]).unwrap();
        assert_eq!(r[0].v, 10.0);
        assert!(r[0].e >= 10.0);
    }

    #[test]
    fn asin_carries_atan2s_allowance_and_its_arguments_errors() {
        let m = module("fn f(x: f32) -> f32 { return asin(x); }");
        let mut i = Interp::new(&m);
        let r = i.run("f", &[0.5]).unwrap();
        assert!((r[0].v - 0.5f64.asin()).abs() < 1e-15);
        // At least atan2's 4096 ULP of the result, and not wildly more at x = 1/2, where
        // sqrt(1 - x^2) is well conditioned.
        let ulp = ulp32(r[0].v);
        assert!(
            r[0].e >= 4096.0 * ulp && r[0].e < 4200.0 * ulp,
            "{}",
            r[0].e / ulp
        );
        assert!(i.run("f", &[1.5]).is_err());
    }

    /// cos(pi u) and sin(pi u), u = a b, reduced as wgsl/iridescence.wgsl reduces them.
    const HALF_TURNS: &str = "fn f(a: f32, b: f32) -> vec2<f32> {
        let u = a * b;
        let n = round(u);
        let s = u - n;
        let h = 0.5 * n;
        let sign = 1.0 - 4.0 * (h - floor(h));
        let x = 3.14159265358979 * s;
        return vec2<f32>(sign * cos(x), sign * sin(x));
    }";

    #[test]
    fn a_reduced_phase_keeps_cos_and_sin_bounded_across_a_half_turn() {
        let m = module(HALF_TURNS);
        let mut i = Interp::new(&m);
        // u = 1001 / 2 within its rounding: n may be 500 or 501 on a GPU, s +-1/2 and the sign
        // with it; each choice keeps its argument in [-pi/2, pi/2].
        let a = f64::from(1001.0f32 / 3.0);
        for (a, b) in [(a, 1.5), (1.0 / 3.0, 1.5), (1234.567, 2.0)] {
            let r = i.run("f", &[a, b]).expect("inside WGSL's promises");
            let u = a * b;
            let (c, s) = (
                (std::f64::consts::PI * u).cos(),
                (std::f64::consts::PI * u).sin(),
            );
            // pi rounded to f32 moves the form by up to 4.4e-8.
            assert!(
                (r[0].v - c).abs() < 1e-7 && (r[1].v - s).abs() < 1e-7,
                "{r:?}"
            );
            // 2^-11 for cos and sin, and pi times u's own error (a few ULP of u), no more:
            // the sign stays paired with its n (uncorrelated, sin's bound would be 2).
            let own = f64::powi(2.0, -11) + 4.0 * std::f64::consts::PI * 2.0 * ulp32(u);
            assert!(r[0].e < own && r[1].e < own, "{} {} {own}", r[0].e, r[1].e);
        }
    }

    #[test]
    fn an_unreduced_phase_is_excluded() {
        let m = module("fn f(x: f32) -> f32 { return cos(x); }");
        let mut i = Interp::new(&m);
        assert!(i.run("f", &[3.0]).is_ok());
        assert!(i.run("f", &[1000.0]).is_err());
    }

    #[test]
    fn a_difference_that_may_join_a_longer_sum_is_not_exact() {
        // 1.5 - 1 alone is exact; inside a sum, through a vector's component or a return
        // (an inlined call's caller may add to it) a reordering may round it.
        for src in [
            "fn f(x: f32, y: f32, z: f32) -> f32 { return x - y + z; }",
            "fn f(x: f32, y: f32, z: f32) -> f32 { let v = vec2<f32>(x - y, z); return v.x * z; }",
            "fn f(x: f32, y: f32, z: f32) -> f32 { return (x - y); }",
            "fn f(x: f32, y: f32, z: f32) -> f32 { return fma(z, z, x - y) * z; }",
        ] {
            let m = module(src);
            let mut i = Interp::new(&m);
            let r = i.run("f", &[1.5, 1.0, 0.3]).unwrap();
            assert!(r[0].e > 0.0, "{src}: {r:?}");
        }
        // Kept out of every sum (a product's operand): exact.
        let m = module("fn f(x: f32, y: f32, z: f32) -> f32 { return (x - y) * 2.0; }");
        let r = Interp::new(&m).run("f", &[1.5, 1.0, 0.3]).unwrap();
        assert_eq!((r[0].v, r[0].e), (1.0, 0.0));
    }

    #[test]
    fn a_vector_sum_is_charged_for_its_reordering() {
        // (1000 + 1) - 1000 per component: a reordering may form 1 - 1000 or 1000 + 1 first,
        // rounded in ULP of about 2000, where the form's own partial sums are exact.
        let m = module(
            "fn f(a: f32, b: f32, c: f32) -> vec2<f32> {
                return vec2<f32>(a, a) + vec2<f32>(b, b) - vec2<f32>(c, c);
            }",
        );
        let r = Interp::new(&m).run("f", &[1000.0, 1.0, 1000.0]).unwrap();
        let scalar = module("fn f(a: f32, b: f32, c: f32) -> f32 { return a + b - c; }");
        let s = Interp::new(&scalar)
            .run("f", &[1000.0, 1.0, 1000.0])
            .unwrap();
        assert!(r[0].e >= 0.5 * ulp32(2000.0), "{r:?}");
        assert_eq!((r[0].v, r[0].e), (s[0].v, s[0].e), "as the scalar chain");
    }

    #[test]
    fn a_subnormal_power_of_two_is_not_an_exact_factor() {
        let tiny = f64::powi(2.0, -140);
        assert!(!power_of_two(Num { v: tiny, e: 0.0 }));
        assert!(power_of_two(Num { v: 0.5, e: 0.0 }));
    }

    #[test]
    fn products_by_powers_of_two_and_sterbenz_differences_are_exact() {
        // The difference is a product's operand, kept out of every sum.
        let m = module("fn f(x: f32, y: f32) -> f32 { return (0.5 * x - y) * 2.0; }");
        let mut i = Interp::new(&m);
        // 0.5 * 3 = 1.5 exactly, 1.5 - 1 exactly (Sterbenz), times 2 exactly.
        let r = i.run("f", &[3.0, 1.0]).unwrap();
        assert_eq!((r[0].v, r[0].e), (1.0, 0.0));
        // 1.5 - 0.1: not within a factor of 2, rounded.
        assert!(i.run("f", &[3.0, 0.1]).unwrap()[0].e > 0.0);
    }

    /// The sampling family's module (erf^-1 and its Newton step).
    fn sampling() -> Module {
        let fams = crate::shaders::families();
        let f = fams
            .into_iter()
            .find(|f| f.name == "sampling")
            .expect("sampling");
        f.module
    }

    #[test]
    fn fma_of_a_power_of_two_is_exact_where_its_sum_is_an_f32() {
        let m = module("fn f(u: f32) -> f32 { return fma(2.0, u, -1.0) * 0.5; }");
        let mut i = Interp::new(&m);
        // 2 u - 1 is an f32 for u in [1/4, 1) (Sterbenz), at u = 0, and for a subnormal u
        // (2 u - 1 rounds to -1 whether u is flushed or not).
        for u in [0.0, 0.25, 0.7, 0.999_999_94, 1.4e-45, 0.125] {
            let u = f64::from(u as f32);
            let r = i.run("f", &[u]).unwrap();
            assert_eq!(r[0].e, 0.0, "u = {u}: {r:?}");
        }
        // 2^-30: -1 + 2^-29 is not an f32: one rounding, at most an ULP of the result.
        let r = i.run("f", &[f64::powi(2.0, -30)]).unwrap();
        assert!(r[0].e > 0.0 && r[0].e <= ulp32(0.5), "{r:?}");
        // Inside a longer sum a reassociation may split it: charged.
        let m = module("fn f(u: f32, z: f32) -> f32 { return (fma(2.0, u, -1.0) + z) * 0.5; }");
        assert!(Interp::new(&m).run("f", &[0.75, 0.1]).unwrap()[0].e > 0.0);
    }

    #[test]
    fn an_azimuth_at_u_0_stays_inside_sin_and_coss_domain() {
        // (2 u - 1) pi' at u = 0 is -pi' exactly: inside [-pi, pi]; charged one rounding
        // of 2 u - 1 it would leave it (pi - pi' is 1.5e-7, an ULP of 1 times pi 3.7e-7).
        let m = module("fn f(u: f32) -> f32 { return cos(fma(2.0, u, -1.0) * 3.1415925); }");
        let mut i = Interp::new(&m);
        for u in [0.0, 1.4e-45, 0.999_999_94] {
            assert!(i.run("f", &[u]).is_ok(), "u = {u}");
        }
    }

    /// S(t) of erf^-1's Newton step at an exact t.
    fn step_at(i: &mut Interp<'_>, t: f64, y: f64, q: f64) -> f64 {
        i.run("brdf_erf_inv_newton", &[t, y, q]).unwrap()[0].v
    }

    #[test]
    fn the_newton_rule_bounds_the_step_over_its_whole_interval() {
        let m = sampling();
        let mut i = Interp::new(&m);
        for y in [-0.9, -0.3, 1e-3, 0.25, 0.5, 0.7, 0.99, 0.999_999] {
            let y = f64::from(y as f32);
            let q = 1.0 - y.abs();
            let x0 = i.run("sampling_erf_inv", &[y]).unwrap()[0].v;
            // Intervals straddling the root off-centre (whose image reaches down to the root
            // between the ends' and the centre's images), centred on it, beside it.
            for (c, e) in [
                (x0, 1e-6),
                (x0, 1e-3),
                (x0 + 5e-3, 1e-2),
                (x0 + 2e-3, 1e-3),
                (x0 - 0.05, 0.02),
            ] {
                let r = i
                    .newton_step("brdf_erf_inv_newton", Num { v: c, e }, &[y, q])
                    .unwrap();
                for k in 0..=2000 {
                    let t = c - e + 2.0 * e * f64::from(k) / 2000.0;
                    let s = step_at(&mut i, t, y, q);
                    assert!(
                        (s - r.v).abs() <= r.e,
                        "y {y}, x in {c} +- {e}: S({t}) = {s} outside {} +- {}",
                        r.v,
                        r.e
                    );
                }
            }
        }
    }

    #[test]
    fn the_newton_rule_squares_the_incoming_error() {
        let m = sampling();
        let mut i = Interp::new(&m);
        let y = f64::from(0.6f32);
        let q = 1.0 - y;
        let x = i.run("sampling_erf_inv", &[y]).unwrap()[0].v;
        // 1e-3 in: Newton leaves about x 1e-6 (f'' / 2 f' = -x); operation by operation the
        // error would pass through twice.
        let r = i
            .newton_step("brdf_erf_inv_newton", Num { v: x, e: 1e-3 }, &[y, q])
            .unwrap();
        assert!(r.e < 1e-5, "{r:?}");
        // S'(x*) = 0: a first-order propagation would carry no error through the step, yet
        // both ends of an interval centred on the root land on the same side of its image,
        // K e^2 away; the rule's hull of the ends and the centre holds them (with the image
        // dropped, the_newton_rule_bounds_the_step_over_its_whole_interval fails at y = -0.9).
        let (lo, hi) = (
            step_at(&mut i, x - 1e-3, y, q),
            step_at(&mut i, x + 1e-3, y, q),
        );
        let root = step_at(&mut i, x, y, q);
        assert!(
            (lo - root) * (hi - root) > 0.0,
            "the ends straddle the root's image: {lo} {root} {hi}"
        );
    }

    #[test]
    fn erf_inv_s_bound_holds_its_f64_kernel_and_stays_a_few_ulp() {
        let m = sampling();
        let mut i = Interp::new(&m);
        let kernel = brdf_ref::KERNELS
            .iter()
            .find(|k| k.path == "sampling::erf_inv")
            .expect("erf_inv's row");
        // y over (-1, 1), and up to the last f32 below 1.
        let grid = (1..2000).map(|k| f64::from(k) / 1000.0 - 1.0);
        let ends = (1..=24).flat_map(|k| {
            let y = 1.0 - f64::powi(2.0, -k);
            [y, -y]
        });
        for y in grid.chain(ends) {
            #[allow(clippy::cast_possible_truncation)]
            let y = f64::from(y as f32);
            let r = i.run("sampling_erf_inv", &[y]).unwrap()[0];
            let mut out = [0.0];
            (kernel.f64)(&[y], &mut out);
            let want = out[0];
            assert!(
                (r.v - want).abs() <= r.e,
                "y {y}: {} +- {} against {want}",
                r.v,
                r.e
            );
            // At y = 0 the result is 0 and its bound the flush allowance 2^-126.
            assert!(
                want == 0.0 || r.e <= 64.0 * ulp32(want),
                "y {y}: bound {} ULP",
                r.e / ulp32(want)
            );
        }
    }

    #[test]
    fn a_value_passed_to_a_newton_step_joins_a_sum_only_where_the_step_adds_it() {
        // 1.5 - 1 is exact alone; passed to a divisor it stays so, passed to a sum it does not.
        let m = module(
            "fn g_newton(q: f32) -> f32 { return 3.0 / q; }
             fn h_newton(q: f32) -> f32 { return q + 0.3; }
             fn f(x: f32, y: f32) -> f32 { return g_newton(x - y) * 2.0; }
             fn k(x: f32, y: f32) -> f32 { return h_newton(x - y) * 2.0; }",
        );
        let mut i = Interp::new(&m);
        // g's division of an exact 0.5, and h's sum of an exact 0.5: only their own roundings.
        let exact_q = i.run("g_newton", &[0.5]).unwrap()[0];
        assert_eq!(i.run("f", &[1.5, 1.0]).unwrap()[0].e, 2.0 * exact_q.e);
        let exact_sum = i.run("h_newton", &[0.5]).unwrap()[0];
        let r = i.run("k", &[1.5, 1.0]).unwrap()[0];
        assert!(r.e > 2.0 * exact_sum.e, "{r:?} {exact_sum:?}");
    }

    #[test]
    fn the_solves_safeguard_takes_the_forms_branch() {
        // The comparison of the test above: uncertain, both operands outside the solve's
        // helpers, the form's only inside them.
        let body = "{ return select(0.0, 10.0, (b * 0.1) * 10.0 - 1.0 >= 0.0); }";
        let m = module(&format!(
            "fn f(b: f32) -> f32 {body} fn {FORM_BRANCHES}f(b: f32) -> f32 {body}"
        ));
        let mut i = Interp::new(&m);
        assert!(i.run("f", &[1.0]).unwrap()[0].e >= 10.0);
        let r = i.run(&format!("{FORM_BRANCHES}f"), &[1.0]).unwrap()[0];
        assert_eq!((r.v, r.e), (10.0, 0.0));
    }
}
