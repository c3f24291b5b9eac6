//! Pinched vertices: where a block's boundary touches itself at a vertex (two joints crossing with
//! the same block in two opposite corners, the block reaching round the others), the triangles of
//! each corner get their own copy of the node. One shared node would glue the two rock corners at
//! a point across both joints, and give the node two pairs of boundary edges where contact
//! detection needs one (its faces' directions and the joint length it carries).

use crate::triangulate::BoundaryEdge;

/// Give each fan of triangles around a pinched vertex its own node: a vertex is pinched when more
/// than one boundary edge starts at it; the triangles around it are grouped by the edges through
/// it they share, the first group keeps the vertex and each other group gets a new node at the
/// same place, appended to `points`, with its boundary edges renumbered. Returns how many nodes
/// were added.
pub fn split_pinches(
    points: &mut Vec<[f64; 2]>,
    triangles: &mut [[u32; 3]],
    boundary: &mut [BoundaryEdge],
) -> usize {
    let mut starts = vec![0u8; points.len()];
    for e in boundary.iter() {
        let s = &mut starts[e.nodes[0] as usize];
        *s = s.saturating_add(1);
    }
    let pinched: Vec<u32> = (0..points.len() as u32)
        .filter(|&v| starts[v as usize] > 1)
        .collect();
    let mut added = 0;
    for v in pinched {
        let around: Vec<usize> = (0..triangles.len())
            .filter(|&t| triangles[t].contains(&v))
            .collect();
        let fans = fans_around(v, triangles, &around);
        for fan in fans.iter().skip(1) {
            let copy = points.len() as u32;
            points.push(points[v as usize]);
            added += 1;
            for &t in fan {
                for n in triangles[t].iter_mut().filter(|n| **n == v) {
                    *n = copy;
                }
            }
            let in_fan = |a: u32, b: u32| {
                fan.iter().any(|&t| {
                    let tri = triangles[t];
                    tri.contains(&a) && tri.contains(&b)
                })
            };
            for e in boundary.iter_mut() {
                let [a, b] = e.nodes;
                if a == v && in_fan(copy, b) {
                    e.nodes[0] = copy;
                } else if b == v && in_fan(a, copy) {
                    e.nodes[1] = copy;
                }
            }
        }
    }
    added
}

/// The triangles `around` vertex v grouped into fans: two triangles are in one fan when they share
/// an edge through v.
fn fans_around(v: u32, triangles: &[[u32; 3]], around: &[usize]) -> Vec<Vec<usize>> {
    let others = |t: usize| {
        let mut o = triangles[t].iter().copied().filter(move |&n| n != v);
        [o.next().unwrap_or(v), o.next().unwrap_or(v)]
    };
    let mut fan_of = vec![usize::MAX; around.len()];
    let mut fans: Vec<Vec<usize>> = Vec::new();
    for seed in 0..around.len() {
        if fan_of[seed] != usize::MAX {
            continue;
        }
        let f = fans.len();
        fan_of[seed] = f;
        let mut fan = vec![around[seed]];
        let mut k = 0;
        while k < fan.len() {
            let ends = others(fan[k]);
            for (i, &t) in around.iter().enumerate() {
                if fan_of[i] == usize::MAX && others(t).iter().any(|n| ends.contains(n)) {
                    fan_of[i] = f;
                    fan.push(t);
                }
            }
            k += 1;
        }
        fans.push(fan);
    }
    fans
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::joints::EdgeKind;

    /// Two triangles meeting only at the origin (a bow tie), as one block's mesh.
    fn bow_tie() -> (Vec<[f64; 2]>, Vec<[u32; 3]>, Vec<BoundaryEdge>) {
        let points = vec![
            [0.0, 0.0],
            [1.0, -0.5],
            [1.0, 0.5],
            [-1.0, 0.5],
            [-1.0, -0.5],
        ];
        let triangles = vec![[0, 1, 2], [0, 3, 4]];
        let kind = EdgeKind::Joint(0);
        let boundary = [[0, 1], [1, 2], [2, 0], [0, 3], [3, 4], [4, 0]]
            .map(|nodes| BoundaryEdge { nodes, kind })
            .to_vec();
        (points, triangles, boundary)
    }

    #[test]
    fn a_bow_tie_gets_a_node_for_each_corner() {
        let (mut points, mut triangles, mut boundary) = bow_tie();
        assert_eq!(split_pinches(&mut points, &mut triangles, &mut boundary), 1);
        assert_eq!(points.len(), 6);
        assert_eq!(points[5], [0.0, 0.0]);
        assert_eq!(triangles, vec![[0, 1, 2], [5, 3, 4]]);
        let starts = |v: u32| boundary.iter().filter(|e| e.nodes[0] == v).count();
        let ends = |v: u32| boundary.iter().filter(|e| e.nodes[1] == v).count();
        for v in 0..6 {
            assert_eq!((starts(v), ends(v)), (1, 1), "node {v}");
        }
        // Each boundary edge still belongs to a triangle.
        for e in &boundary {
            assert!(
                triangles
                    .iter()
                    .any(|t| e.nodes.iter().all(|n| t.contains(n)))
            );
        }
    }

    #[test]
    fn a_fan_round_an_ordinary_vertex_is_left_alone() {
        // A square cut into four triangles round its centre: the corners are not pinched.
        let mut points = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.5, 0.5]];
        let mut triangles = vec![[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]];
        let kind = EdgeKind::Region(0);
        let mut boundary = [[0, 1], [1, 2], [2, 3], [3, 0]]
            .map(|nodes| BoundaryEdge { nodes, kind })
            .to_vec();
        let before = triangles.clone();
        assert_eq!(split_pinches(&mut points, &mut triangles, &mut boundary), 0);
        assert_eq!((points.len(), triangles), (5, before));
    }
}
