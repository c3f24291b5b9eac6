//! The factor of safety by strength reduction (issue 49): blocks on planes against limit
//! equilibrium, explicitly and implicitly.

use std::fmt::Write as _;

use crate::case::{Case, Context, Section, print_row, table, verdict};
use crate::strength_reduction::{BLOCKS, run};

/// Bar: the factor of safety within 1 % of limit equilibrium's, and the explicit and implicit
/// searches within 1 % of each other.
const BAR: f64 = 0.01;

pub struct StrengthReduction;

impl Case for StrengthReduction {
    fn name(&self) -> &'static str {
        "strength_reduction"
    }

    fn run(&self, _cx: &Context) -> anyhow::Result<Section> {
        let (mut rows, mut missed) = (Vec::new(), Vec::new());
        for block in &BLOCKS {
            let mut factors = Vec::new();
            for &method in block.methods() {
                let (r, found) = run(block, method)?;
                print_row(&r);
                if r.errors["factor"] > BAR {
                    missed.push(format!("{}: {:?} beyond {BAR}", r.case, r.errors));
                }
                factors.push(found.factor);
                rows.push(r);
            }
            let apart = match factors[..] {
                [e, i] => (e - i).abs() / e,
                _ => 0.0,
            };
            if apart > BAR {
                missed.push(format!(
                    "{}: explicit {:.4} and implicit {:.4} differ by {:.2} %",
                    block.name(),
                    factors[0],
                    factors[1],
                    100.0 * apart
                ));
            }
        }
        let mut md = String::new();
        let _ = writeln!(
            md,
            "\n## Factor of safety by strength reduction: a block on a plane (issue 49)\n"
        );
        let _ = writeln!(
            md,
            "A 2 m × 0.5 m block (ρ 2 600 kg/m³) on a joint over a 10 m × 1 m base fixed at its \
             bottom, gravity tilted by the plane's dip α; one stage that settles and then searches \
             its factor of safety (`stages[i].factor_of_safety`, tolerance 0.002: the strengths \
             of the zones and joints divided by F, each trial solved again from the stage's \
             equilibrium, F doubled, then bisected between the largest stable and the smallest \
             unstable factor), against limit equilibrium's FoS = (c A + W cos α tan φ)/(W sin α) \
             (Hoek & Bray's plane failure without water). The joint keeps its cohesion when it \
             slips (`residual_cohesion` = `cohesion`), as limit equilibrium's uniform \
             mobilization assumes. The last two rows put a rigid block on the joint laws whose \
             strength lives in each contact's state, reduced at every state (`docs/theory.md`): \
             a Barton–Bandis joint (JRC and JCS measured over the block's 2 m, Kni 2e10 Pa/m, \
             Vm 0.1 mm, Kmax 4e10 Pa/m), whose factor is ∫ τp(σn(x)) dx / (W sin α) with \
             τp = σn tan(φr + JRC log10(JCS/σn)) over the rigid block's linear σn(x) (its \
             resultant (h/2) tan α downslope of the base's centre; every point of the base \
             slips alike and peaks at the same δp; each trial released over 10 000 cycles, \
             `solve.ramp`: released at once, the block gains speed while its joint mobilizes its \
             roughness and slides past the peak, 1.7 % below the closed form), and a \
             continuously yielding joint with φm0 = φ, whose bound |σn| tan φ gives \
             tan φ / tan α. Both explicitly only: the implicit path refuses the continuously \
             yielding law, and does not settle the Barton–Bandis block's own gravity stage \
             (from a zero shear path its joint climbs the rising branch, whose slope is a small \
             fraction of the ks in its matrix: 500 iterations leave the block moving 3e-5 m an \
             iteration). `factor`: |F − FoS| / FoS with F the largest stable factor; \
             `bracket`: (F_unstable − F) / FoS; cycles: the stage's and every trial's (an \
             unstable explicit trial runs to `max_cycles`, 30 000; implicitly, iterations). \
             Bars (issue 49): within {} % of limit equilibrium, explicit and implicit within \
             {} % of each other: {}.\n",
            100.0 * BAR,
            100.0 * BAR,
            verdict(&missed)
        );
        table(&mut md, &rows);
        Ok(Section {
            markdown: md,
            rows,
            missed,
            ..Default::default()
        })
    }
}
