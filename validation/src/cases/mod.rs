//! The report's sections, one module each, in the order `docs/validation.md` gives them: each
//! runs its case and writes its own explanation, tables and plots.

mod barton_bandis;
mod column;
mod column_slide;
mod corners;
mod detection;
mod direct_shear;
mod energy;
mod equivalent;
mod far_field;
mod flow_network;
mod free_field;
mod glued;
mod grains;
mod gravity;
mod hoek_brown;
mod impact;
mod implicit;
mod incline;
mod inclusion;
mod incompressible;
mod joint_waves;
mod kirsch;
mod lamb;
mod lined;
mod miller;
mod modes;
mod newmark;
mod pao_mow;
mod patch;
mod plastic_zoning;
mod pullout;
mod quiet;
mod random_scenes;
mod recovery;
mod rotation;
mod salencon;
mod scale;
mod shallow;
mod slivers;
mod slope;
mod slope_hb;
mod softening;
mod spalling;
mod stiff_joints;
mod strength_reduction;
mod tunnel;
mod ubiquitous;
mod unstable;

use crate::case::Case;

/// Every case, in the report's order.
pub fn all() -> Vec<Box<dyn Case>> {
    vec![
        Box::new(kirsch::Kirsch),
        Box::new(implicit::Implicit),
        Box::new(far_field::FarField),
        Box::new(recovery::Recovery),
        Box::new(patch::Patch),
        Box::new(gravity::Gravity),
        Box::new(salencon::Salencon),
        Box::new(plastic_zoning::PlasticZoning),
        Box::new(hoek_brown::HoekBrown),
        Box::new(hoek_brown::HoekBrownBrittle),
        Box::new(ubiquitous::Ubiquitous),
        Box::new(spalling::Spalling),
        Box::new(lined::Lined),
        Box::new(pullout::Pullout),
        Box::new(tunnel::Tunnel),
        Box::new(scale::Scale),
        Box::new(incompressible::Incompressible),
        Box::new(inclusion::Inclusion),
        Box::new(impact::Impact),
        Box::new(stiff_joints::StiffJoints),
        Box::new(corners::Corners),
        Box::new(slivers::Slivers),
        Box::new(grains::Grains),
        Box::new(softening::Softening),
        Box::new(rotation::Rotation),
        Box::new(random_scenes::RandomScenes),
        Box::new(unstable::Unstable),
        Box::new(glued::Glued),
        Box::new(equivalent::Equivalent),
        Box::new(incline::Incline),
        Box::new(direct_shear::DirectShear),
        Box::new(barton_bandis::BartonBandis),
        Box::new(modes::Modes),
        Box::new(detection::Detection),
        Box::new(column::Column),
        Box::new(column_slide::ColumnSlide),
        Box::new(strength_reduction::StrengthReduction),
        Box::new(slope::Slope),
        Box::new(slope_hb::SlopeHoekBrown),
        Box::new(quiet::Quiet),
        Box::new(free_field::FreeField),
        Box::new(joint_waves::JointWaves),
        Box::new(miller::Miller),
        Box::new(lamb::Lamb),
        Box::new(pao_mow::PaoMow),
        Box::new(newmark::NewmarkBlock),
        Box::new(energy::EnergyBalance),
        Box::new(flow_network::FlowNetwork),
    ]
}
