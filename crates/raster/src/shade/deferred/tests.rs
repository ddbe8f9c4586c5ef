use super::*;

/// Every order of `frags` (primitive index, fixed-point depth) at one
/// pixel through [`unordered_test`] leaves the depth and the winner that
/// draw order leaves under `func` (depths written, `stored` before the
/// draw).
fn check_orders(func: CompareFunc, stored: u32, frags: &[(u32, u32)]) {
    // Draw order: the plain test, the last to pass wins.
    let (mut want_z, mut want_w) = (stored, NO_PRIM);
    let mut sorted = frags.to_vec();
    sorted.sort_by_key(|f| f.0);
    for &(p, z) in &sorted {
        if func.test(z, want_z) {
            (want_z, want_w) = (z, p);
        }
    }
    let n = frags.len();
    let mut order: Vec<usize> = (0..n).collect();
    // Heap's algorithm over every permutation.
    let mut c = vec![0usize; n];
    let run = |order: &[usize]| {
        let mut depth = [stored];
        let mut winner = [(NO_PRIM, 0u8)];
        for &i in order {
            let (p, z) = frags[i];
            let with = (&mut depth[..], &winner[..], 1);
            let (pass, _) = unordered_test(with, func, (0, 0), (1, [z; 4], p));
            if pass & 1 != 0 {
                winner[0] = (p, 0xf);
            }
        }
        assert_eq!(
            (depth[0], winner[0].0),
            (want_z, want_w),
            "{func:?}, stored {stored}, {frags:?} in order {order:?}"
        );
    };
    run(&order);
    let mut i = 0;
    while i < n {
        if c[i] < i {
            let j = if i % 2 == 0 { 0 } else { c[i] };
            order.swap(j, i);
            run(&order);
            c[i] += 1;
            i = 0;
        } else {
            c[i] = 0;
            i += 1;
        }
    }
}

#[test]
fn out_of_order_depth_tests_keep_what_draw_order_keeps() {
    use CompareFunc::*;
    // Ties among fragments, with the stored depth, and none.
    let cases: [(u32, &[(u32, u32)]); 5] = [
        (100, &[(0, 50), (1, 50), (2, 50)]),
        (50, &[(0, 50), (1, 50), (2, 40), (3, 40)]),
        (100, &[(0, 70), (1, 30), (2, 30), (3, 70), (4, 100)]),
        (20, &[(0, 50), (1, 50), (2, 20), (3, 60)]),
        (60, &[(0, 10), (1, 60), (2, 90), (3, 60), (4, 10)]),
    ];
    for func in [Less, LessEqual, Greater, GreaterEqual] {
        for &(stored, frags) in &cases {
            check_orders(func, stored, frags);
        }
    }
}

#[test]
fn bounds_out_of_order_let_ties_through() {
    use CompareFunc::*;
    // A bound equal to the stored depth may belong to a fragment that wins
    // its tie out of draw order: not rejected then.
    for (func, tied) in [(Less, LessEqual), (Greater, GreaterEqual)] {
        assert_eq!(ties_pass(func), tied);
        assert!(!func.test(5u32, 5) && ties_pass(func).test(5u32, 5));
    }
    for func in [LessEqual, GreaterEqual] {
        assert_eq!(ties_pass(func), func);
    }
}
