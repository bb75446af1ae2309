//! The order of an entry of a best-first search (`BinaryHeap`, largest
//! first) by one float field, with `f64::total_cmp`: the branch and bound
//! over vertices (`measure/vertices.rs`), over curvature cells
//! (`measure/curvature.rs`) and over certified membership cells
//! (`set/certify.rs`).

/// `heap_ordered_by!(Type, field)`: `PartialEq`, `Eq`, `PartialOrd` and
/// `Ord` of `Type` by its `f64` field `field` alone (`total_cmp`), so that a
/// `BinaryHeap<Type>` pops the largest `field` first.
macro_rules! heap_ordered_by {
    ($ty:ident, $field:ident) => {
        impl PartialEq for $ty {
            fn eq(&self, other: &Self) -> bool {
                self.$field.total_cmp(&other.$field) == std::cmp::Ordering::Equal
            }
        }
        impl Eq for $ty {}
        impl PartialOrd for $ty {
            fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
                Some(self.cmp(other))
            }
        }
        impl Ord for $ty {
            fn cmp(&self, other: &Self) -> std::cmp::Ordering {
                self.$field.total_cmp(&other.$field)
            }
        }
    };
}

pub(crate) use heap_ordered_by;
