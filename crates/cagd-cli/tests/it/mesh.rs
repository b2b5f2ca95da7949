//! Mesh export read back by real mesh readers: `stl_io` (binary STL), `tobj` (OBJ) and
//! `ply-rs` (ASCII and binary PLY). Counts, coordinates and orientation are checked.

use std::io::Cursor;

use cagd::grid::PointGrid;

use cagd_cli::mesh::{encode, triangulate, write, MeshError, MeshFormat};
use cagd_octave::literal::{Env, ParamExpr};

/// The surface z = u − u² + v over [0,1]², sampled nu × nv (a graph over the plane, so
/// x_u × x_v points upwards everywhere).
fn graph(nu: usize, nv: usize) -> PointGrid<f64> {
    let e = ParamExpr::parse("[u; v; u-u^2+v]").unwrap();
    e.sample_surface(
        &mut Env::<f64>::new(),
        &cagd::linspace(0.0, 1.0, nu),
        &cagd::linspace(0.0, 1.0, nv),
    )
    .unwrap()
}

/// A patch whose edge v = 0 collapses to one point (a triangular patch, as a Coons patch with
/// a degenerate boundary curve): the first triangle-pair of every cell on that edge loses one.
fn collapsed(n: usize) -> PointGrid<f64> {
    let e = ParamExpr::parse("[u.*v; v; v.*(1-v)]").unwrap();
    let t = cagd::linspace(0.0, 1.0, n);
    e.sample_surface(&mut Env::<f64>::new(), &t, &t).unwrap()
}

fn upward(n: [f64; 3]) -> bool {
    n[2] > 0.0
}

/// Consistent orientation: neighbouring triangles run through their shared edge in opposite
/// directions, so no directed edge occurs twice.
fn assert_consistently_oriented(triangles: impl IntoIterator<Item = [usize; 3]>) {
    let mut seen = std::collections::HashSet::new();
    for [a, b, c] in triangles {
        for edge in [(a, b), (b, c), (c, a)] {
            assert!(seen.insert(edge), "directed edge {edge:?} occurs twice");
        }
    }
}

fn cross(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> [f64; 3] {
    let (u, v) = (
        [b[0] - a[0], b[1] - a[1], b[2] - a[2]],
        [c[0] - a[0], c[1] - a[1], c[2] - a[2]],
    );
    [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ]
}

#[test]
fn binary_stl_reads_back() {
    let (nu, nv) = (7, 5);
    let grid = graph(nu, nv);
    let bytes = encode(&grid, MeshFormat::Stl).unwrap();
    assert_eq!(bytes.len(), 84 + 50 * 2 * (nu - 1) * (nv - 1));
    let mesh = stl_io::read_stl(&mut Cursor::new(&bytes)).unwrap();
    assert_eq!(mesh.faces.len(), 2 * (nu - 1) * (nv - 1));
    // stl_io merges equal vertices: every grid point is distinct here.
    assert_eq!(mesh.vertices.len(), nu * nv);
    assert_consistently_oriented(mesh.faces.iter().map(|f| f.vertices));
    for f in &mesh.faces {
        let n = f.normal.0;
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        assert!((len - 1.0).abs() < 1e-6, "unit normals");
        assert!(n[2] > 0.0, "consistent upward orientation");
        let [a, b, c] = f.vertices.map(|k| mesh.vertices[k].0.map(f64::from));
        let m = cross(a, b, c);
        assert!(upward(m), "vertex order agrees with the stored normal");
    }
}

#[test]
fn obj_reads_back_exactly() {
    let (nu, nv) = (6, 9);
    let grid = graph(nu, nv);
    let bytes = encode(&grid, MeshFormat::Obj).unwrap();
    let (models, _) = tobj::load_obj_buf(
        &mut Cursor::new(&bytes),
        &tobj::LoadOptions::default(),
        |_| Err(tobj::LoadError::OpenFileFailed),
    )
    .unwrap();
    assert_eq!(models.len(), 1);
    let m = &models[0].mesh;
    assert_eq!(m.positions.len(), 3 * nu * nv);
    assert_eq!(m.indices.len(), 3 * 2 * (nu - 1) * (nv - 1));
    // tobj renumbers vertices in the order faces use them; as a set they are the grid points,
    // written so that they read back to the same doubles.
    let key = |p: [f64; 3]| p.map(f64::to_bits);
    let mut read: Vec<_> = m
        .positions
        .chunks(3)
        .map(|p| key([p[0], p[1], p[2]]))
        .collect();
    let mut expected: Vec<_> = (0..nu)
        .flat_map(|i| (0..nv).map(move |j| (i, j)))
        .map(|(i, j)| key([grid[[i, j, 0]], grid[[i, j, 1]], grid[[i, j, 2]]]))
        .collect();
    read.sort();
    expected.sort();
    assert_eq!(read, expected);
    assert_consistently_oriented(
        m.indices
            .chunks(3)
            .map(|t| [t[0] as usize, t[1] as usize, t[2] as usize]),
    );
    for t in m.indices.chunks(3) {
        let p = |k: u32| {
            let k = k as usize;
            [
                m.positions[3 * k],
                m.positions[3 * k + 1],
                m.positions[3 * k + 2],
            ]
        };
        assert!(upward(cross(p(t[0]), p(t[1]), p(t[2]))));
    }
}

fn read_ply(bytes: &[u8]) -> ply_rs_bw::ply::Ply<ply_rs_bw::ply::DefaultElement> {
    let parser = ply_rs_bw::parser::Parser::<ply_rs_bw::ply::DefaultElement>::new();
    parser.read_ply(&mut Cursor::new(bytes)).unwrap()
}

fn check_ply(grid: &PointGrid<f64>, bytes: &[u8], faces: usize) {
    use ply_rs_bw::ply::Property;
    let (nu, nv, _) = grid.dim();
    let ply = read_ply(bytes);
    let vertices = &ply.payload["vertex"];
    let face_list = &ply.payload["face"];
    assert_eq!(vertices.len(), nu * nv);
    assert_eq!(face_list.len(), faces);
    let coord = |k: usize, name: &str| match vertices[k][name] {
        Property::Double(x) => x,
        ref other => panic!("expected a double, got {other:?}"),
    };
    for i in 0..nu {
        for j in 0..nv {
            let k = i * nv + j;
            assert_eq!(
                [coord(k, "x"), coord(k, "y"), coord(k, "z")],
                [grid[[i, j, 0]], grid[[i, j, 1]], grid[[i, j, 2]]]
            );
        }
    }
    let mut triangles = Vec::new();
    for f in face_list {
        let Property::ListInt(ref idx) = f["vertex_indices"] else {
            panic!("expected an int list");
        };
        assert_eq!(idx.len(), 3);
        assert!(idx.iter().all(|&k| k >= 0 && (k as usize) < nu * nv));
        triangles.push([idx[0] as usize, idx[1] as usize, idx[2] as usize]);
    }
    assert_consistently_oriented(triangles);
}

#[test]
fn ascii_and_binary_ply_read_back() {
    let grid = graph(4, 3);
    check_ply(&grid, &encode(&grid, MeshFormat::PlyAscii).unwrap(), 12);
    check_ply(&grid, &encode(&grid, MeshFormat::PlyBinary).unwrap(), 12);
}

#[test]
fn degenerate_triangles_are_skipped() {
    let n = 5;
    let grid = collapsed(n);
    let mesh = triangulate(&grid).unwrap();
    // The row v = 0 is a single point: one triangle of each of the n−1 cells along it
    // has two equal vertices.
    assert_eq!(mesh.skipped, n - 1);
    assert_eq!(mesh.triangles.len(), 2 * (n - 1) * (n - 1) - (n - 1));
    assert_eq!(mesh.vertices.len(), n * n);
    let bytes = encode(&grid, MeshFormat::Stl).unwrap();
    let stl = stl_io::read_stl(&mut Cursor::new(&bytes)).unwrap();
    assert_eq!(stl.faces.len(), mesh.triangles.len());
    // stl_io merges the n coincident points of the collapsed edge into one.
    assert_eq!(stl.vertices.len(), n * n - (n - 1));
    check_ply(
        &grid,
        &encode(&grid, MeshFormat::PlyAscii).unwrap(),
        mesh.triangles.len(),
    );
}

#[test]
fn write_chooses_the_format_by_extension_and_leaves_nothing_on_error() {
    let dir = tempfile::tempdir().unwrap();
    let grid = graph(3, 3);
    for (name, magic) in [
        ("a.stl", &b"binary STL"[..]),
        ("a.OBJ", b"# triangulated"),
        ("a.ply", b"ply\nformat ascii"),
    ] {
        let path = dir.path().join(name);
        write(&grid, &path).unwrap();
        assert!(std::fs::read(&path).unwrap().starts_with(magic), "{name}");
    }
    assert!(matches!(
        write(&grid, &dir.path().join("a.vtk")),
        Err(MeshError::UnknownExtension { .. })
    ));
    assert!(matches!(
        write(
            &PointGrid::from_elem((1, 3, 3), 0.0),
            &dir.path().join("b.stl")
        ),
        Err(MeshError::Shape { nu: 1, .. })
    ));
    assert!(matches!(
        write(&grid, &dir.path().join("missing/c.stl")),
        Err(MeshError::Io { .. })
    ));
    let mut names: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    assert_eq!(
        names,
        vec!["a.OBJ", "a.ply", "a.stl"],
        "no temporary or partial files"
    );
}
