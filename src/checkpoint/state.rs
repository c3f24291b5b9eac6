//! The model's state a stage leaves: every array that a solve or a stage changes. What `setup`
//! makes from the scene alone (zone connectivity, block ranges, the far field's stiffness, the
//! laws, which the stages' replay restores) is not saved; its sizes are checked instead.

use super::codec::{Codec, Reader, put};
use crate::joint::JointState;
use crate::model::{MaterialId, Model};

impl Codec for MaterialId {
    fn put(&self, out: &mut Vec<u8>) {
        self.0.put(out);
    }
    fn get(r: &mut Reader) -> anyhow::Result<Self> {
        Ok(MaterialId(u32::get(r)?))
    }
}

impl Codec for JointState {
    fn put(&self, out: &mut Vec<u8>) {
        for x in [
            self.normal,
            self.shear,
            self.shear_displacement,
            self.normal_displacement,
            self.initial_normal,
            self.dilation,
            self.bounding_friction,
            self.reversal,
            self.shear_path,
            self.jrc_mobilized,
        ] {
            x.put(out);
        }
        self.flags.put(out);
    }
    fn get(r: &mut Reader) -> anyhow::Result<Self> {
        let [
            normal,
            shear,
            shear_displacement,
            normal_displacement,
            initial_normal,
            dilation,
            bounding_friction,
            reversal,
            shear_path,
            jrc_mobilized,
        ] = <[f64; 10]>::get(r)?;
        Ok(JointState {
            normal,
            shear,
            shear_displacement,
            normal_displacement,
            initial_normal,
            dilation,
            bounding_friction,
            reversal,
            shear_path,
            jrc_mobilized,
            flags: u8::get(r)?,
        })
    }
}

/// A saved array that must have `len` items (the model's own count of them).
fn same<T: Codec>(r: &mut Reader, len: usize, what: &str) -> anyhow::Result<Vec<T>> {
    let v = Vec::<T>::get(r)?;
    anyhow::ensure!(
        v.len() == len,
        "the checkpoint's {what} has {} items where the scene builds {len} (not this scene's?)",
        v.len()
    );
    Ok(v)
}

/// Write the state of `model`.
pub fn save(model: &Model, out: &mut Vec<u8>) {
    let n = &model.nodes;
    put(out, &n.pos);
    put(out, &n.disp);
    put(out, &n.origin);
    put(out, &n.vel);
    put(out, &n.force);
    put(out, &n.mass);
    put(out, &n.applied);
    put(out, &n.fixed);
    let z = &model.zones;
    put(out, &z.area);
    put(out, &z.grad);
    put(out, &z.stress);
    put(out, &z.material);
    put(out, &z.state);
    put(out, &z.plastic);
    put(out, &model.mixed);
    put(out, &model.blocks.removed);
    let b = &model.bodies;
    put(out, &b.centroid);
    put(out, &b.velocity);
    put(out, &b.mass);
    put(out, &b.force);
    put(out, &b.weight);
    put(out, &b.area);
    put(out, &b.radius);
    put(out, &b.material);
    put(out, &b.stress);
    put(out, &b.state);
    put(out, &b.plastic);
    put(out, &b.constraint);
    put(out, &b.projector);
    put(out, &b.step);
    let c = &model.contacts;
    put(out, &c.node);
    put(out, &c.edge);
    put(out, &c.block);
    put(out, &c.xi);
    put(out, &c.length);
    put(out, &c.material);
    put(out, &c.corner);
    put(out, &c.state);
    let k = &model.supports.cables;
    put(out, &k.active);
    put(out, &k.disp);
    put(out, &k.vel);
    put(out, &k.force);
    put(out, &k.applied);
    put(out, &k.mass);
    put(out, &k.rock_origin);
    put(out, &k.grout_force);
    put(out, &k.slip);
    put(out, &k.axial);
    put(out, &k.plastic);
    let l = &model.supports.liners;
    put(out, &l.active);
    put(out, &l.disp);
    put(out, &l.vel);
    put(out, &l.force);
    put(out, &l.mass);
    put(out, &l.link_origin);
    put(out, &l.axial);
    put(out, &l.moment);
    put(out, &model.far_field.as_ref().map(|f| f.attached.clone()));
}

/// Put the state read from `r` into `model`, which `setup` built from the same scene and the
/// stages before replayed: an error when a count differs (another scene's checkpoint).
pub fn restore(model: &mut Model, r: &mut Reader) -> anyhow::Result<()> {
    let n = &mut model.nodes;
    let nodes = n.len();
    n.pos = same(r, nodes, "node positions")?;
    n.disp = same(r, nodes, "node displacements")?;
    n.origin = same(r, nodes, "node origins")?;
    n.vel = same(r, nodes, "node velocities")?;
    n.force = same(r, nodes, "node forces")?;
    n.mass = same(r, nodes, "node masses")?;
    n.applied = same(r, nodes, "node loads")?;
    n.fixed = same(r, nodes, "node fixities")?;
    let z = &mut model.zones;
    let zones = z.len();
    z.area = same(r, zones, "zone areas")?;
    z.grad = same(r, zones, "zone gradients")?;
    z.stress = same(r, zones, "zone stresses")?;
    z.material = same(r, zones, "zone materials")?;
    z.state = same(r, zones, "zone states")?;
    z.plastic = same(r, zones, "zone plastic strains")?;
    model.mixed = Codec::get(r)?;
    model.blocks.removed = Codec::get(r)?;
    anyhow::ensure!(
        model.blocks.removed.len() <= model.blocks.len(),
        "the checkpoint's excavated blocks outnumber the scene's blocks (not this scene's?)"
    );
    let b = &mut model.bodies;
    let bodies = b.len();
    b.centroid = same(r, bodies, "body centroids")?;
    b.velocity = same(r, bodies, "body velocities")?;
    b.mass = same(r, bodies, "body masses")?;
    b.force = same(r, bodies, "body forces")?;
    b.weight = same(r, bodies, "body weights")?;
    b.area = same(r, bodies, "body areas")?;
    b.radius = same(r, bodies, "body radii")?;
    b.material = same(r, bodies, "body materials")?;
    b.stress = same(r, bodies, "body stresses")?;
    b.state = same(r, bodies, "body states")?;
    b.plastic = same(r, bodies, "body plastic strains")?;
    b.constraint = same(r, bodies, "body constraints")?;
    b.projector = same(r, bodies, "body projectors")?;
    b.step = same(r, bodies, "body strain steps")?;
    let c = &mut model.contacts;
    c.node = Codec::get(r)?;
    let contacts = c.node.len();
    c.edge = same(r, contacts, "contact edges")?;
    c.block = same(r, contacts, "contact blocks")?;
    c.xi = same(r, contacts, "contact positions")?;
    c.length = same(r, contacts, "contact lengths")?;
    c.material = same(r, contacts, "contact materials")?;
    c.corner = same(r, contacts, "contact corners")?;
    c.state = same(r, contacts, "contact states")?;
    let (nodes, edges) = (model.nodes.len(), model.blocks.edges.len());
    anyhow::ensure!(
        c.node.iter().all(|&v| (v as usize) < nodes)
            && c.edge.iter().all(|&e| (e as usize) < edges),
        "the checkpoint's contacts name nodes or edges the scene does not have (not this scene's?)"
    );
    model.contacts = std::mem::take(&mut model.contacts).indexed(nodes, &model.blocks.edges);
    let k = &mut model.supports.cables;
    k.active = same(r, k.active.len(), "bolt groups")?;
    let cable = k.nodes();
    k.disp = same(r, cable, "bolt displacements")?;
    k.vel = same(r, cable, "bolt velocities")?;
    k.force = same(r, cable, "bolt forces")?;
    k.applied = same(r, cable, "bolt loads")?;
    k.mass = same(r, cable, "bolt masses")?;
    k.rock_origin = same(r, cable, "bolt rock origins")?;
    k.grout_force = same(r, cable, "grout forces")?;
    k.slip = same(r, cable, "grout slips")?;
    let segments = k.segment.len();
    k.axial = same(r, segments, "bolt axial forces")?;
    k.plastic = same(r, segments, "bolt plastic elongations")?;
    let l = &mut model.supports.liners;
    l.active = same(r, l.active.len(), "liners")?;
    let liner = l.nodes();
    l.disp = same(r, liner, "liner displacements")?;
    l.vel = same(r, liner, "liner velocities")?;
    l.force = same(r, liner, "liner forces")?;
    l.mass = same(r, liner, "liner masses")?;
    l.link_origin = same(r, l.link_node.len(), "liner link origins")?;
    let elements = l.element.len();
    l.axial = same(r, elements, "liner axial forces")?;
    l.moment = same(r, elements, "liner moments")?;
    let attached: Option<Vec<[f64; 2]>> = Codec::get(r)?;
    match (&mut model.far_field, attached) {
        (Some(f), Some(a)) if a.len() == f.attached.len() => f.attached = a,
        (None, None) => {}
        _ => anyhow::bail!("the checkpoint's far field is not the scene's"),
    }
    Ok(())
}
