//! The model's state a stage leaves: every array that a solve or a stage changes. What `setup`
//! makes from the scene alone (zone connectivity, block ranges, the far field's stiffness, the
//! laws, which the stages' replay restores) is not saved; its sizes are checked instead.

use super::codec::{Codec, Reader, put};
use crate::joint::JointState;
use crate::model::{MaterialId, Model};
use crate::support::{Cables, Liners};

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
    save_supports(model, out);
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
    restore_supports(model, r)?;
    let attached: Option<Vec<[f64; 2]>> = Codec::get(r)?;
    match (&mut model.far_field, attached) {
        (Some(f), Some(a)) if a.len() == f.attached.len() => f.attached = a,
        (None, None) => {}
        _ => anyhow::bail!("the checkpoint's far field is not the scene's"),
    }
    Ok(())
}

/// The items of `values` at `at`.
fn pick<T: Clone>(values: &[T], at: &[usize]) -> Vec<T> {
    at.iter().map(|&i| values[i].clone()).collect()
}

/// Read as many items as `at` holds into `values` at `at`.
fn scatter<T: Codec>(
    r: &mut Reader,
    values: &mut [T],
    at: &[usize],
    what: &str,
) -> anyhow::Result<()> {
    for (v, &i) in same::<T>(r, at.len(), what)?.into_iter().zip(at) {
        values[i] = v;
    }
    Ok(())
}

/// Where each installed bolt group's state lies: its cable nodes and its segments.
fn cable_items(k: &Cables, g: u32) -> (Vec<usize>, Vec<usize>) {
    let nodes = (0..k.nodes()).filter(|&n| k.group[n] == g).collect();
    let segments = (0..k.segment.len())
        .filter(|&s| k.segment_group[s] == g)
        .collect();
    (nodes, segments)
}

/// Where each installed liner's state lies: its nodes, its links and its elements.
fn liner_items(l: &Liners, g: u32) -> (Vec<usize>, Vec<usize>, Vec<usize>) {
    let nodes = (0..l.nodes()).filter(|&n| l.group[n] == g).collect();
    let links = (0..l.link_node.len())
        .filter(|&k| l.group[l.link_node[k] as usize] == g)
        .collect();
    let elements = (0..l.element.len())
        .filter(|&e| l.element_group[e] == g)
        .collect();
    (nodes, links, elements)
}

/// The state of each installed bolt group and liner, by name: the supports a later stage
/// installs hold none yet, and a scene that branches from this checkpoint may define them
/// otherwise.
fn save_supports(model: &Model, out: &mut Vec<u8>) {
    let k = &model.supports.cables;
    let groups: Vec<u32> = (0..k.names.len() as u32)
        .filter(|&g| k.active[g as usize])
        .collect();
    put(out, &groups.len());
    for &g in &groups {
        let (n, s) = cable_items(k, g);
        put(out, &k.names[g as usize]);
        put(out, &pick(&k.disp, &n));
        put(out, &pick(&k.vel, &n));
        put(out, &pick(&k.force, &n));
        put(out, &pick(&k.applied, &n));
        put(out, &pick(&k.mass, &n));
        put(out, &pick(&k.rock_origin, &n));
        put(out, &pick(&k.grout_force, &n));
        put(out, &pick(&k.rock_last, &n));
        put(out, &pick(&k.absorbed, &n));
        put(out, &pick(&k.slip, &n));
        put(out, &pick(&k.axial, &s));
        put(out, &pick(&k.plastic, &s));
    }
    let l = &model.supports.liners;
    let liners: Vec<u32> = (0..l.names.len() as u32)
        .filter(|&g| l.active[g as usize])
        .collect();
    put(out, &liners.len());
    for &g in &liners {
        let (n, links, e) = liner_items(l, g);
        put(out, &l.names[g as usize]);
        put(out, &pick(&l.disp, &n));
        put(out, &pick(&l.vel, &n));
        put(out, &pick(&l.force, &n));
        put(out, &pick(&l.mass, &n));
        put(out, &pick(&l.link_origin, &links));
        put(out, &pick(&l.axial, &e));
        put(out, &pick(&l.moment, &e));
    }
}

/// The index of the support named `name` among `names`, installed (`active`) in the scene's
/// stages so far: an error naming it otherwise.
fn installed(names: &[String], active: &[bool], name: &str, kind: &str) -> anyhow::Result<u32> {
    let g = names.iter().position(|n| n == name).ok_or_else(|| {
        anyhow::anyhow!("the checkpoint's {kind} '{name}' is not in the scene (not this scene's?)")
    })?;
    anyhow::ensure!(
        active[g],
        "the checkpoint's {kind} '{name}' is installed, the scene's is not yet (not this scene's?)"
    );
    Ok(g as u32)
}

/// Put the saved state of the installed supports into `model`'s, group by group by name; every
/// support the stages so far installed must be saved.
fn restore_supports(model: &mut Model, r: &mut Reader) -> anyhow::Result<()> {
    let k = &mut model.supports.cables;
    let groups = usize::get(r)?;
    anyhow::ensure!(
        groups == k.active.iter().filter(|&&a| a).count(),
        "the checkpoint holds {groups} installed bolt group(s), the scene's stages so far install \
         {} (not this scene's?)",
        k.active.iter().filter(|&&a| a).count()
    );
    for _ in 0..groups {
        let name = String::get(r)?;
        let g = installed(&k.names, &k.active, &name, "bolt group")?;
        let (n, s) = cable_items(k, g);
        scatter(r, &mut k.disp, &n, "bolt displacements")?;
        scatter(r, &mut k.vel, &n, "bolt velocities")?;
        scatter(r, &mut k.force, &n, "bolt forces")?;
        scatter(r, &mut k.applied, &n, "bolt loads")?;
        scatter(r, &mut k.mass, &n, "bolt masses")?;
        scatter(r, &mut k.rock_origin, &n, "bolt rock origins")?;
        scatter(r, &mut k.grout_force, &n, "grout forces")?;
        scatter(r, &mut k.rock_last, &n, "bolt rock displacements")?;
        scatter(r, &mut k.absorbed, &n, "bolt energies")?;
        scatter(r, &mut k.slip, &n, "grout slips")?;
        scatter(r, &mut k.axial, &s, "bolt axial forces")?;
        scatter(r, &mut k.plastic, &s, "bolt plastic elongations")?;
    }
    let l = &mut model.supports.liners;
    let liners = usize::get(r)?;
    anyhow::ensure!(
        liners == l.active.iter().filter(|&&a| a).count(),
        "the checkpoint holds {liners} installed liner(s), the scene's stages so far install {} \
         (not this scene's?)",
        l.active.iter().filter(|&&a| a).count()
    );
    for _ in 0..liners {
        let name = String::get(r)?;
        let g = installed(&l.names, &l.active, &name, "liner")?;
        let (n, links, e) = liner_items(l, g);
        scatter(r, &mut l.disp, &n, "liner displacements")?;
        scatter(r, &mut l.vel, &n, "liner velocities")?;
        scatter(r, &mut l.force, &n, "liner forces")?;
        scatter(r, &mut l.mass, &n, "liner masses")?;
        scatter(r, &mut l.link_origin, &links, "liner link origins")?;
        scatter(r, &mut l.axial, &e, "liner axial forces")?;
        scatter(r, &mut l.moment, &e, "liner moments")?;
    }
    Ok(())
}
