//! Disjoint sets over the items 0..n (union–find with path halving): which items a set of joins
//! connects. Each set is represented by its smallest item.

/// The sets, as a parent per item.
pub struct UnionFind {
    parent: Vec<usize>,
}

impl UnionFind {
    /// `n` items, each in a set of its own.
    pub fn new(n: usize) -> UnionFind {
        UnionFind {
            parent: (0..n).collect(),
        }
    }

    /// The representative (smallest item) of `x`'s set.
    pub fn root(&mut self, mut x: usize) -> usize {
        let parent = &mut self.parent;
        while parent[x] != x {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        x
    }

    /// Join the sets of `a` and `b`.
    pub fn join(&mut self, a: usize, b: usize) {
        let (ra, rb) = (self.root(a), self.root(b));
        self.parent[ra.max(rb)] = ra.min(rb);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn joins_connect_chains_and_the_smallest_item_represents_each_set() {
        let mut u = UnionFind::new(6);
        u.join(4, 2);
        u.join(2, 5);
        u.join(3, 1);
        assert_eq!(
            [0, 1, 2, 1, 2, 2].to_vec(),
            (0..6).map(|i| u.root(i)).collect::<Vec<_>>()
        );
    }
}
