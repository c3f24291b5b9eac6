//! Joint realizations: the main model builds as its joint sets move (issue 14). The drawn
//! realizations are in `validation/src/realizations.rs`.

use adit::Scene;

/// Moving set 0's origin across ±1 m in 5 cm steps (20 of 40 positions failed before).
#[test]
fn tunnel_model_builds_as_a_set_moves_in_small_steps() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let base = Scene::load(&root.join("models/tunnel.json")).unwrap();
    let failed: Vec<String> = (0..=40)
        .filter_map(|k| {
            let mut sc = base.clone();
            sc.joint_sets[0].origin[0] += -1.0 + 0.05 * k as f64;
            adit::setup::setup(&sc)
                .err()
                .map(|e| format!("step {k}: {e}"))
        })
        .collect();
    assert!(failed.is_empty(), "{}", failed.join("\n"));
}

/// The realization that still failed after the mesher's fix: set 1 crosses the crown of the
/// horseshoe 0.071 m from its vertex (inside the 0.075 m merge tolerance), 0.022 m short of where
/// it crosses set 0 outside the wall. The wall's split merged into its crown and the joint's into
/// the joint crossing off the wall, and the joint piece crossed the wall; crossings now merge onto
/// the wall first.
#[test]
fn a_joint_crossing_a_wall_near_a_corner_merges_onto_the_wall() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut sc = Scene::load(&root.join("models/tunnel.json")).unwrap();
    let sets = [
        (
            36.57868761970316,
            2.346695969597309,
            [-1.0994839388580386, -0.6635481243366879],
            11.28779149383049,
        ),
        (
            95.14954346084268,
            3.051663131796084,
            [0.2497796919717558, -0.5658813868166002],
            10.005397717343358,
        ),
    ];
    for (set, (dip, spacing, origin, trace)) in sc.joint_sets.iter_mut().zip(sets) {
        set.dip = dip;
        set.spacing = spacing;
        set.origin = origin;
        set.trace = Some(trace);
    }
    adit::setup::setup(&sc).unwrap();
}

/// Realizations of the tunnel model (origins ± spacing, dips ± 15°, spacings and traces
/// × U(0.6, 1.4)) with a sliver of rock along the tunnel's staged wall, all its vertices within
/// the merge tolerance of the wall: taken for the tunnel's fill, it was excavated, and the bolt
/// whose head it held "left the rock" (3 of 1 000 such realizations). A block fills a hole by
/// where its area lies; these slivers stay rock, and nothing outside the profile goes with the
/// fill.
#[test]
fn rock_slivers_along_a_staged_wall_stay_rock() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let base = Scene::load(&root.join("models/tunnel.json")).unwrap();
    // (dip °, spacing m, origin m, trace m) of sets 0 and 1.
    type Set = (f64, f64, [f64; 2], f64);
    let realizations: [[Set; 2]; 3] = [
        [
            (
                36.53431627276702,
                1.6210860004541574,
                [0.7079218218024851, 1.8096632273527746],
                13.82438311401655,
            ),
            (
                94.72976200524296,
                3.8355578753562214,
                [-0.7180060832585882, -1.1546843847074826],
                11.979760968009803,
            ),
        ],
        [
            (
                38.61387923423747,
                2.8527166509683726,
                [2.7884252083006458, 2.4511084002885033],
                13.662845271981796,
            ),
            (
                99.3708880747872,
                3.6212019151251993,
                [-2.23034637947623, 2.1376056928185445],
                6.089957398371474,
            ),
        ],
        [
            (
                28.95538338611699,
                1.6496211782713066,
                [2.767003350530191, -1.4323304647335846],
                10.10460058967863,
            ),
            (
                109.72514806665666,
                4.042842704081448,
                [-2.332822265663143, -0.36730482987718904],
                11.593842309964732,
            ),
        ],
    ];
    for sets in realizations {
        let mut sc = base.clone();
        for (set, (dip, spacing, origin, trace)) in sc.joint_sets.iter_mut().zip(sets) {
            (set.dip, set.spacing, set.origin, set.trace) = (dip, spacing, origin, Some(trace));
        }
        let built = adit::setup::setup(&sc).unwrap_or_else(|e| panic!("{sets:?}: {e:#}"));
        assert!(
            !built
                .warnings
                .iter()
                .any(|w| w.contains("outside its profile")),
            "{:?}",
            built.warnings
        );
    }
}

/// A box of half-width `half`, m, with a circular hole of `radius` (m) at `centre` (m), cut by
/// non-persistent sets (dip °, spacing m, origin m, trace m, gap m): the scene the proptest
/// `random_sets_in_a_box_with_a_hole_build_and_tile` draws.
fn box_scene(
    half: f64,
    centre: [f64; 2],
    radius: f64,
    sets: &[(f64, f64, [f64; 2], f64, f64)],
) -> Scene {
    let joint_sets: Vec<serde_json::Value> = sets
        .iter()
        .map(|(dip, spacing, origin, trace, gap)| {
            serde_json::json!({ "dip": dip, "spacing": spacing, "origin": origin,
                "trace": trace, "gap": gap, "material": "joint" })
        })
        .collect();
    let scene = serde_json::json!({
        "name": "box",
        "materials": { "rock": { "density": 2600, "young": 10e9, "poisson": 0.25 } },
        "region": { "polygon": [[-half, -half], [half, -half], [half, half], [-half, half]], "material": "rock" },
        "excavations": [ { "name": "hole", "circle": { "center": centre, "radius": radius, "segments": 48 } } ],
        "zoning": { "edge_at_excavation": 0.25, "edge_far": 2.0 },
        "joint_materials": { "joint": { "normal_stiffness": 1e10, "shear_stiffness": 5e9, "friction": 30 } },
        "joint_sets": joint_sets,
    });
    Scene::from_json(&scene.to_string(), "box").unwrap()
}

/// `box_scene` with a hole of 0.5 m at its middle meshes into blocks and zones that fill the box
/// less the hole (`drawn::assert_tiles`).
fn box_with_sets_tiles(half: f64, sets: &[(f64, f64, [f64; 2], f64, f64)]) {
    drawn::assert_tiles(&box_scene(half, [0.0, 0.0], 0.5, sets)).unwrap();
}

/// Drawn boxes that stopped with "block boundary crosses itself" (the proptest under
/// `PROPTEST_RNG_SEED` 20261126 and 101), each from vertices merging within the tolerance
/// (0.059 m here). In the first, sets 0 and 2 cross at 3.9° and set 1 ends between them, 0.045 m
/// from set 0 and 0.009 m from set 2: merging took set 2's split there onto set 0, and set 2's
/// piece to the crossing ran through set 0's split between them (to round-off), a block of no
/// area; the piece is now split there and counts once. In the second, sets 0 and 2 cross
/// 0.059 m from set 0's crossing with set 1 and 0.047 m from set 2's: set 0's split there merged
/// into the one, set 2's into the other, and their pieces crossed; set 0's piece is now split at
/// the vertex set 2's went to.
#[test]
fn joints_merged_onto_each_other_leave_blocks_that_do_not_cross_themselves() {
    box_with_sets_tiles(
        10.439377443027722,
        &[
            (
                157.53865901951204,
                2.234292514380411,
                [-0.7779699547653266, 1.4982781472671853],
                5.477275606064478,
                0.0,
            ),
            (
                129.64385778324018,
                1.4063678660357877,
                [-2.2430782965109977, 2.1342724313908543],
                4.273023887495583,
                2.114278082502702,
            ),
            (
                154.2712419718653,
                3.9969739606202555,
                [1.199507459380759, 0.8441147256581825],
                9.899742905602997,
                0.0,
            ),
        ],
    );
    box_with_sets_tiles(
        16.286685277019544,
        &[
            (
                94.83750745590402,
                2.256211645580437,
                [3.736800487484077, -4.795319252697244],
                11.998324626851986,
                3.8566662768383475,
            ),
            (
                130.2372282952411,
                3.3689231175797096,
                [4.863619758403148, 1.2315794442309937],
                5.037390931036659,
                3.570323782063004,
            ),
            (
                176.45940013585798,
                1.1527190369938622,
                [-0.22431007080610618, 1.869211569214007],
                6.520869370223935,
                2.360644614631909,
            ),
        ],
    );
}

/// Two sets 0.1° apart around a horseshoe (a drawn scene that stopped with "zoning.accept_angle:
/// a zone of block 16 … has an angle of 0.42°"): the pieces of joint that made the needles are
/// dropped, each named in a warning, and every zone keeps at least the accepted angle; with
/// `accept_angle` 0 nothing is dropped.
#[test]
fn joints_meeting_at_a_tiny_angle_lose_the_piece_that_makes_a_needle() {
    let text = r#"{ "name": "f", "materials": { "rock": { "density": 2500, "young": 1e10, "poisson": 0.25 } },
      "joint_materials": { "j": { "normal_stiffness": 1e10, "shear_stiffness": 1e9, "friction": 30 } },
      "region": { "polygon": [[-13.6124, -8.0277], [13.6124, -8.0277], [13.6124, 8.0277], [-13.6124, 8.0277]], "material": "rock" },
      "excavations": [{ "name": "t", "horseshoe": { "center": [0, 0], "radius": 2.38866, "wall_height": 0.91331 } }],
      "joint_sets": [
        { "dip": 96.2777, "spacing": 0.385145, "origin": [0.405480, -1.118548], "trace": 10.93947, "gap": 1.93969, "material": "j" },
        { "dip": 96.1720, "spacing": 1.566017, "origin": [2.328915, -1.223305], "trace": 8.01597, "gap": 1.58997, "material": "j" }],
      "zoning": { "edge_at_excavation": 0.10710, "edge_far": 0.85677 ACCEPT } }"#;
    let repaired = Scene::from_json(&text.replace(" ACCEPT", ""), "f").unwrap();
    let built = adit::setup::setup(&repaired).unwrap();
    let drops: Vec<&String> = built
        .warnings
        .iter()
        .filter(|w| w.starts_with("joint_sets[") && w.contains("dropped the piece"))
        .collect();
    assert!(!drops.is_empty(), "{:?}", built.warnings);
    assert!(
        built.mesh.min_angle_deg >= repaired.zoning.accept_angle,
        "{}",
        built.mesh.min_angle_deg
    );
    let any = Scene::from_json(&text.replace(" ACCEPT", ", \"accept_angle\": 0"), "f").unwrap();
    let built = adit::setup::setup(&any).unwrap();
    assert!(built.warnings.iter().all(|w| !w.contains("dropped")));
    assert!(built.mesh.min_angle_deg < repaired.zoning.accept_angle);
}

mod drawn {
    use adit::Scene;
    use adit::scene::Scatter;
    use adit::setup::mesh;
    use adit_meshing::Polygon;
    use proptest::prelude::*;

    /// Blocks tile the region: their areas (outline less holes) sum to the region's less the
    /// excavations that are holes from the start, to round-off; so do the zones, and none is
    /// sharper than the scene accepts.
    pub(super) fn assert_tiles(scene: &Scene) -> Result<(), TestCaseError> {
        let meshed = mesh(scene).map_err(|e| TestCaseError::fail(format!("{e:#}")))?;
        let region = Polygon::new(scene.region.polygon.clone())
            .signed_area()
            .abs();
        let open: f64 = meshed
            .domain
            .holes
            .iter()
            .zip(&scene.excavations)
            .filter(|(_, e)| !scene.is_staged(&e.name))
            .map(|(h, _)| h.polygon.signed_area().abs())
            .sum();
        let blocks: f64 = meshed
            .blocking
            .blocks
            .iter()
            .map(|b| {
                b.outer.signed_area().abs()
                    - b.holes.iter().map(|h| h.signed_area().abs()).sum::<f64>()
            })
            .sum();
        let want = region - open;
        prop_assert!(
            (blocks - want).abs() < 1e-9 * region,
            "blocks {blocks} vs {want}"
        );
        let zoned = meshed.stats().area;
        prop_assert!(
            (zoned - want).abs() < 1e-9 * region,
            "zones {zoned} vs {want}"
        );
        // No zone sharper than `zoning.accept_angle`: the pieces of joint that made such zones
        // were dropped, each a reported repair.
        if let Some((angle, at, block)) = meshed.sharpest_zone() {
            prop_assert!(
                angle >= scene.zoning.accept_angle,
                "a zone of {angle}° at {at:?} in block {block}; repairs: {:?}",
                meshed.repairs
            );
        }
        Ok(())
    }

    fn tunnel() -> Scene {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        Scene::load(&root.join("models/tunnel.json")).unwrap()
    }

    proptest! {
        #![proptest_config(ProptestConfig {
            cases: 160,
            rng_seed: proptest::test_runner::RngSeed::Fixed(14),
            failure_persistence: None,
            ..ProptestConfig::default()
        })]

        /// Realizations of the tunnel model's sets, with scatters up to the full spacing, ±15°
        /// and ±40 %, build and tile the region.
        #[test]
        fn tunnel_realizations_build_and_tile(
            n in 1u64..1_000_000_000,
            origin in 0.0f64..3.0,
            dip in 0.0f64..15.0,
            fraction in 0.0f64..0.4,
        ) {
            let mut s = tunnel();
            for set in &mut s.joint_sets {
                set.scatter = Some(Scatter { origin, dip, spacing: fraction, trace: fraction, gap: fraction });
            }
            s.realization = n;
            assert_tiles(&s)?;
        }

        /// Random non-persistent sets in a box with a circular hole build and tile the box. (A hole
        /// whose segments were shorter than the merge tolerance lost slivers to the blocks.)
        #[test]
        fn random_sets_in_a_box_with_a_hole_build_and_tile(
            half in 6.0f64..20.0,
            radius in 0.5f64..2.5,
            centre in (-0.5f64..0.5, -0.5f64..0.5),
            sets in prop::collection::vec(
                (0.0f64..180.0, 0.8f64..4.0, (-5.0f64..5.0, -5.0f64..5.0), 2.0f64..15.0, 0.0f64..4.0),
                1..4,
            ),
        ) {
            let c = [centre.0 * half, centre.1 * half];
            let sets: Vec<_> = sets.iter().map(|&(dip, spacing, o, trace, gap)| (dip, spacing, [o.0, o.1], trace, gap)).collect();
            assert_tiles(&super::box_scene(half, c, radius, &sets))?;
        }
    }
}

/// Realizations of the tunnel study (origins ±2 m, dips ±10°, spacings and traces ±30 %) that
/// built but ran away in the in-situ stage: in 8 a one-zone wedge's apex sat in a notch of the
/// block round it with one contact carrying both faces along one normal; in 31 a block touched
/// itself where two joints cross, one node glued its two corners and carried two pairs of edges;
/// in 10 a wedge's tip pressed into the block across its joint took that block's nearer free face
/// and was pushed out of the model. Each now settles.
#[test]
fn tunnel_realizations_that_ran_away_settle_in_situ() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let base = Scene::load(&root.join("models/tunnel.json")).unwrap();
    let study = adit::scene::Scatter {
        origin: 2.0,
        dip: 10.0,
        spacing: 0.3,
        trace: 0.3,
        gap: 0.0,
    };
    for n in [8, 10, 31] {
        let mut sc = base.clone();
        for set in &mut sc.joint_sets {
            set.scatter = Some(study);
        }
        sc.realization = n;
        let mut b = adit::setup::setup(&sc).unwrap();
        let mut solver = adit::solve::Solver::new(&mut b.model, &sc.solve, 0);
        let sol = solver.solve(&mut b.model, &mut adit::solve::Quiet);
        assert_eq!(
            sol.status,
            adit::solve::Status::Converged,
            "realization {n}: {:?}",
            sol.status
        );
    }
}
