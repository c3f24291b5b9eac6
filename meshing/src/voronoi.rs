//! Grain-based blocks: the Voronoi tessellation of jittered seeds (spade's Delaunay triangulation
//! and its dual), as joint segments to cut the region with.

use spade::{DelaunayTriangulation, Point2, Triangulation};

use crate::error::MeshError;
use crate::geometry::Point;
use crate::joints::{EdgeKind, Segment, SplitMix};
use crate::union_find::UnionFind;

/// Voronoi edges shorter than this many grain sizes collapse into a vertex.
pub const SHORTEST_EDGE: f64 = 0.1;

/// Voronoi edges over the box `lo`–`hi` (m) for grains of about `size` (m): one seed per cell of a
/// `size` grid, jittered by up to ±0.45 `size` (seeded, reproducible), over the box grown by two
/// cells so that every cell meeting the box is closed, edges shorter than `SHORTEST_EDGE` grain
/// sizes collapsed. Edges wholly outside the grown box are dropped; the region cut clips the rest.
pub fn voronoi_segments(
    lo: Point,
    hi: Point,
    size: f64,
    seed: u64,
    kind: EdgeKind,
) -> Result<Vec<Segment>, MeshError> {
    if !(size > 0.0 && size.is_finite()) {
        return Err(MeshError::Zoning(
            "voronoi grain size must be positive".into(),
        ));
    }
    let margin = 2.0 * size;
    // Counted in floating point: a tiny size must not overflow the product.
    let (fx, fy) = (
        ((hi[0] - lo[0] + 2.0 * margin) / size).ceil(),
        ((hi[1] - lo[1] + 2.0 * margin) / size).ceil(),
    );
    if (fx * fy).is_nan() || fx * fy > 4e6 {
        return Err(MeshError::Zoning(format!(
            "{:.4e} voronoi grains are too many",
            fx * fy
        )));
    }
    let (nx, ny) = (fx as usize, fy as usize);
    let mut rng = SplitMix(seed);
    let mut seeds = Vec::with_capacity(nx * ny);
    for i in 0..nx {
        for j in 0..ny {
            let x = lo[0] - margin + (i as f64 + 0.5 + 0.45 * rng.symmetric()) * size;
            let y = lo[1] - margin + (j as f64 + 0.5 + 0.45 * rng.symmetric()) * size;
            seeds.push(Point2::new(x, y));
        }
    }
    let dt = crate::triangulate::guarded(|| {
        DelaunayTriangulation::<Point2<f64>>::bulk_load_stable(seeds)
            .map_err(|e| MeshError::Triangulation(format!("voronoi seeds: {e:?}")))
    })?;
    let inside = |p: Point2<f64>| {
        p.x >= lo[0] - margin
            && p.x <= hi[0] + margin
            && p.y >= lo[1] - margin
            && p.y <= hi[1] + margin
    };
    // Voronoi vertices are the circumcentres of the Delaunay faces. Those joined by an edge shorter
    // than `SHORTEST_EDGE` grain sizes merge into their mean (union–find over faces): a grain
    // vertex between two very short edges would stand for a tiny contact length and press deep into
    // its neighbour.
    let faces = dt.num_all_faces();
    let mut sets = UnionFind::new(faces);
    let mut edges = Vec::new();
    for edge in dt.undirected_voronoi_edges() {
        let [a, b] = edge.vertices();
        if let (Some(fa), Some(fb)) = (a.as_delaunay_face(), b.as_delaunay_face()) {
            let (pa, pb) = (fa.circumcenter(), fb.circumcenter());
            if !(inside(pa) || inside(pb)) {
                continue;
            }
            let (ia, ib) = (fa.fix().index(), fb.fix().index());
            if (pa.x - pb.x).hypot(pa.y - pb.y) < SHORTEST_EDGE * size {
                sets.join(ia, ib);
            } else {
                edges.push((ia, ib));
            }
        }
    }
    let mut sum = vec![[0.0f64; 3]; faces];
    for face in dt.inner_faces() {
        let i = face.fix().index();
        let c = face.circumcenter();
        let r = sets.root(i);
        sum[r][0] += c.x;
        sum[r][1] += c.y;
        sum[r][2] += 1.0;
    }
    let mut seen = crate::Set::default();
    let mut out = Vec::new();
    for (ia, ib) in edges {
        let (ra, rb) = (sets.root(ia), sets.root(ib));
        if ra == rb || !seen.insert((ra.min(rb), ra.max(rb))) {
            continue;
        }
        let at = |r: usize| [sum[r][0] / sum[r][2], sum[r][1] / sum[r][2]];
        out.push(Segment {
            a: at(ra),
            b: at(rb),
            kind,
        });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::blocks::{Block, cut_blocks};
    use crate::domain::Domain;
    use crate::geometry::{Polygon, orient};
    use approx::assert_relative_eq;

    #[test]
    fn voronoi_grains_tile_the_region_with_convex_blocks() {
        let outer = Polygon::new(vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]);
        let d = Domain::new(outer, (0..4).map(|i| format!("e{i}")).collect(), vec![]).unwrap();
        let segs = voronoi_segments([0.0, 0.0], [10.0, 10.0], 1.0, 7, EdgeKind::Joint(0)).unwrap();
        assert!(
            segs.iter()
                .all(|s| (s.b[0] - s.a[0]).hypot(s.b[1] - s.a[1]) >= SHORTEST_EDGE),
            "a short edge survived"
        );
        let b = cut_blocks(&d, &segs, 1e-6).unwrap();
        // About one grain per m², plus the cut cells along the boundary.
        assert!(
            (100..=140).contains(&b.blocks.len()),
            "{} grains",
            b.blocks.len()
        );
        assert_relative_eq!(
            b.blocks.iter().map(Block::area).sum::<f64>(),
            100.0,
            max_relative = 1e-9
        );
        for k in &b.blocks {
            let n = k.outer.len();
            for i in 0..n {
                let (p, q, r) = (
                    k.outer.vertices[i],
                    k.outer.vertices[(i + 1) % n],
                    k.outer.vertices[(i + 2) % n],
                );
                assert!(orient(p, q, r) >= -1e-9, "grain is not convex");
            }
        }
        let again = voronoi_segments([0.0, 0.0], [10.0, 10.0], 1.0, 7, EdgeKind::Joint(0)).unwrap();
        assert_eq!(segs, again);
    }
}
