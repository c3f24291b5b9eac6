use adit::solve::Quiet;
fn main() -> anyhow::Result<()> {
    for f in ["near_implicit", "nearC", "boxF50", "boxF100b", "boxF100"] {
        let sc = adit::Scene::load(std::path::Path::new(&format!("/tmp/sh/{f}.json")))?;
        let out = std::env::temp_dir().join("probe_sh");
        let _ = std::fs::remove_dir_all(&out);
        let r = adit::run_scene(&sc, &out, &mut Quiet)?;
        let m = &r.built.model;
        let near = |p: [f64; 2]| {
            let i = (0..m.nodes.pos.len())
                .min_by(|&a, &b| {
                    let d = |i: usize| (m.nodes.pos[i][0] - p[0]).hypot(m.nodes.pos[i][1] - p[1]);
                    d(a).total_cmp(&d(b))
                })
                .unwrap();
            m.nodes.disp[i]
        };
        let (crown, invert, left, right) = (
            near([0.0, -4.0]),
            near([0.0, -8.0]),
            near([-2.0, -6.0]),
            near([2.0, -6.0]),
        );
        let (s0, s6) = (near([0.0, 0.0]), near([6.0, 0.0]));
        println!(
            "{f}: zones {} vertical conv {:.4} mm, horizontal conv {:.4} mm, surface(0)-surface(6) {:.4} mm, {:.2}s",
            r.summary.zones,
            1e3 * (crown[1] - invert[1]),
            1e3 * (left[0] - right[0]),
            1e3 * (s0[1] - s6[1]),
            r.summary.wall_seconds
        );
    }
    Ok(())
}
