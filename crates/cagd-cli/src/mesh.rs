//! Triangulated surfaces for Blender, MeshLab, ParaView and 3-D printers.
//!
//! A sampled surface is a grid of shape (nu, nv, 3) — `grid[[i, j, k]]` is coordinate `k` of
//! the point at `(u_i, v_j)`, the thesis's `P(i,j,:)`. [`triangulate`] turns it into a
//! triangle mesh: vertex `i·nv + j` is grid point (i, j), and every grid cell
//! `(i, j), (i+1, j), (i+1, j+1), (i, j+1)` becomes the two triangles
//! `[(i,j), (i+1,j), (i+1,j+1)]` and `[(i,j), (i+1,j+1), (i,j+1)]`. Both run
//! counter-clockwise when seen from the side the normal `x_u × x_v` points to, so the
//! orientation is consistent over the whole surface.
//!
//! **Degenerate triangles** (zero area: two equal vertices or three collinear ones, as where a
//! boundary curve collapses to a point) are skipped and counted in
//! [`TriangleMesh::skipped`]; they carry no surface and have no normal. Vertices are kept
//! as they are (coincident grid points are not merged), so vertex counts are always nu·nv.
//!
//! Formats ([`MeshFormat`], chosen by extension): binary STL (`.stl`; per-triangle vertices in
//! single precision with unit normals), ASCII OBJ (`.obj`) and ASCII PLY (`.ply`) with vertices
//! in double precision written as the shortest decimal that reads back exactly, and binary
//! little-endian PLY ([`MeshFormat::PlyBinary`]).
//!
//! ```
//! use cagd_cli::mesh::{encode, triangulate, MeshFormat};
//! use cagd::grid::PointGrid;
//!
//! // The bilinear patch through four corners, sampled 3 × 3.
//! let grid = PointGrid::from_shape_fn((3, 3, 3), |(i, j, k)| {
//!     let (u, v) = (i as f64 / 2.0, j as f64 / 2.0);
//!     [u, v, u * v][k]
//! });
//! let mesh = triangulate(&grid).unwrap();
//! assert_eq!((mesh.vertices.len(), mesh.triangles.len(), mesh.skipped), (9, 8, 0));
//! let obj = String::from_utf8(encode(&grid, MeshFormat::Obj).unwrap()).unwrap();
//! assert!(obj.contains("\nf 1 4 5\n"));
//! ```

use std::fmt::Write as _;
use std::path::Path;

use cagd::grid::PointGrid;

/// What can go wrong when exporting a mesh.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum MeshError {
    /// The file name does not end in `.stl`, `.obj` or `.ply`.
    #[error("{path}: unknown mesh format; expected a file name ending in .stl, .obj or .ply")]
    UnknownExtension {
        /// The path given.
        path: String,
    },
    /// The grid is not (nu, nv, 2 or 3) with nu, nv ≥ 2.
    #[error("grid of shape ({nu}, {nv}, {dim}): expected (nu, nv, 3) with nu, nv ≥ 2")]
    Shape {
        /// Points in u.
        nu: usize,
        /// Points in v.
        nv: usize,
        /// Coordinates per point.
        dim: usize,
    },
    /// A NaN or infinite coordinate.
    #[error("grid value at flat index {index} is not finite")]
    NonFinite {
        /// Index in the grid's row-major order.
        index: usize,
    },
    /// A coordinate beyond the single-precision range of binary STL (±3.4e38): it would be
    /// written as infinite.
    #[error(
        "grid value at flat index {index} is {value:e}, beyond the ±{:e} of binary STL",
        f32::MAX
    )]
    OutOfRange {
        /// Index in the grid's row-major order.
        index: usize,
        /// The value.
        value: f64,
    },
    /// More triangles than a binary STL can count, or than the export allows.
    #[error("grid of {points} points is too large to export (at most {limit})")]
    TooLarge {
        /// Grid points.
        points: usize,
        /// The limit.
        limit: usize,
    },
    /// Writing the file failed.
    #[error("{path}: {message}")]
    Io {
        /// The path.
        path: String,
        /// The I/O error.
        message: String,
    },
}

/// Most grid points exported (about 64 MB of binary STL per million points).
pub const MAX_POINTS: usize = 16_000_000;

/// Mesh file formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MeshFormat {
    /// Binary STL.
    Stl,
    /// Wavefront OBJ (ASCII).
    Obj,
    /// Stanford PLY, ASCII.
    PlyAscii,
    /// Stanford PLY, binary little-endian.
    PlyBinary,
}

impl MeshFormat {
    /// The format named by the extension of `path` (case-insensitive): `.stl` binary STL,
    /// `.obj` OBJ, `.ply` ASCII PLY.
    pub fn from_path(path: &Path) -> Result<MeshFormat, MeshError> {
        match path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)
            .as_deref()
        {
            Some("stl") => Ok(MeshFormat::Stl),
            Some("obj") => Ok(MeshFormat::Obj),
            Some("ply") => Ok(MeshFormat::PlyAscii),
            _ => Err(MeshError::UnknownExtension {
                path: path.display().to_string(),
            }),
        }
    }
}

/// A triangle mesh: vertices and triangles (indices into `vertices`, from 0).
#[derive(Debug, Clone, PartialEq)]
pub struct TriangleMesh {
    /// Vertex `i·nv + j` is grid point (i, j).
    pub vertices: Vec<[f64; 3]>,
    /// Triangles, counter-clockwise about `x_u × x_v`.
    pub triangles: Vec<[usize; 3]>,
    /// Degenerate (zero-area) triangles left out.
    pub skipped: usize,
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn normal(mesh: &TriangleMesh, t: [usize; 3]) -> [f64; 3] {
    let [a, b, c] = t.map(|k| mesh.vertices[k]);
    cross(sub(b, a), sub(c, a))
}

/// Triangulates a grid of shape (nu, nv, 3) (or (nu, nv, 2), placed at z = 0) with
/// nu, nv ≥ 2. See the module documentation for the vertex order, the orientation and the
/// treatment of degenerate triangles.
pub fn triangulate(grid: &PointGrid<f64>) -> Result<TriangleMesh, MeshError> {
    let (nu, nv, dim) = grid.dim();
    if nu < 2 || nv < 2 || !(2..=3).contains(&dim) {
        return Err(MeshError::Shape { nu, nv, dim });
    }
    let points = nu.saturating_mul(nv);
    if points > MAX_POINTS {
        return Err(MeshError::TooLarge {
            points,
            limit: MAX_POINTS,
        });
    }
    if let Some(index) = grid.iter().position(|x| !x.is_finite()) {
        return Err(MeshError::NonFinite { index });
    }
    let mut vertices = Vec::with_capacity(points);
    for i in 0..nu {
        for j in 0..nv {
            let z = if dim == 3 { grid[[i, j, 2]] } else { 0.0 };
            vertices.push([grid[[i, j, 0]], grid[[i, j, 1]], z]);
        }
    }
    let mut mesh = TriangleMesh {
        vertices,
        triangles: Vec::with_capacity(2 * (nu - 1) * (nv - 1)),
        skipped: 0,
    };
    let at = |i: usize, j: usize| i * nv + j;
    for i in 0..nu - 1 {
        for j in 0..nv - 1 {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            for t in [[a, b, c], [a, c, d]] {
                if normal(&mesh, t) == [0.0; 3] {
                    mesh.skipped += 1;
                } else {
                    mesh.triangles.push(t);
                }
            }
        }
    }
    Ok(mesh)
}

/// A coordinate as the shortest decimal that reads back to the same double.
fn coordinate(x: f64) -> String {
    let a = x.abs();
    if x == 0.0 {
        "0".into()
    } else if (1e-5..1e15).contains(&a) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// Binary STL of a mesh.
pub fn to_stl(mesh: &TriangleMesh) -> Vec<u8> {
    let mut out = Vec::with_capacity(84 + 50 * mesh.triangles.len());
    let mut header = [b' '; 80];
    let title = b"binary STL written by cagd: triangulated surface";
    header[..title.len()].copy_from_slice(title);
    out.extend_from_slice(&header);
    // The caller's size limit keeps the count far below u32::MAX.
    out.extend_from_slice(&(mesh.triangles.len() as u32).to_le_bytes());
    for &t in &mesh.triangles {
        let n = normal(mesh, t);
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        let unit = if len > 0.0 && len.is_finite() {
            n.map(|c| c / len)
        } else {
            [0.0; 3]
        };
        for c in unit {
            out.extend_from_slice(&(c as f32).to_le_bytes());
        }
        for k in t {
            for c in mesh.vertices[k] {
                out.extend_from_slice(&(c as f32).to_le_bytes());
            }
        }
        out.extend_from_slice(&0u16.to_le_bytes());
    }
    out
}

/// ASCII OBJ of a mesh (indices from 1, as OBJ counts).
pub fn to_obj(mesh: &TriangleMesh) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "# triangulated surface written by cagd: {} vertices, {} triangles",
        mesh.vertices.len(),
        mesh.triangles.len()
    );
    for v in &mesh.vertices {
        let _ = writeln!(
            out,
            "v {} {} {}",
            coordinate(v[0]),
            coordinate(v[1]),
            coordinate(v[2])
        );
    }
    for t in &mesh.triangles {
        let _ = writeln!(out, "f {} {} {}", t[0] + 1, t[1] + 1, t[2] + 1);
    }
    out
}

fn ply_header(mesh: &TriangleMesh, format: &str) -> String {
    format!(
        "ply\nformat {format} 1.0\ncomment triangulated surface written by cagd\n\
         element vertex {}\nproperty double x\nproperty double y\nproperty double z\n\
         element face {}\nproperty list uchar int vertex_indices\nend_header\n",
        mesh.vertices.len(),
        mesh.triangles.len()
    )
}

/// ASCII PLY of a mesh (double-precision vertices).
pub fn to_ply_ascii(mesh: &TriangleMesh) -> String {
    let mut out = ply_header(mesh, "ascii");
    for v in &mesh.vertices {
        let _ = writeln!(
            out,
            "{} {} {}",
            coordinate(v[0]),
            coordinate(v[1]),
            coordinate(v[2])
        );
    }
    for t in &mesh.triangles {
        let _ = writeln!(out, "3 {} {} {}", t[0], t[1], t[2]);
    }
    out
}

/// Binary little-endian PLY of a mesh (double-precision vertices, 32-bit indices).
pub fn to_ply_binary(mesh: &TriangleMesh) -> Vec<u8> {
    let mut out = ply_header(mesh, "binary_little_endian").into_bytes();
    for v in &mesh.vertices {
        for c in v {
            out.extend_from_slice(&c.to_le_bytes());
        }
    }
    for t in &mesh.triangles {
        out.push(3);
        for &k in t {
            // Vertex counts are limited to MAX_POINTS, far below i32::MAX.
            out.extend_from_slice(&(k as i32).to_le_bytes());
        }
    }
    out
}

/// Triangulates `grid` and encodes it in `format`.
pub fn encode(grid: &PointGrid<f64>, format: MeshFormat) -> Result<Vec<u8>, MeshError> {
    let mesh = triangulate(grid)?;
    if format == MeshFormat::Stl {
        // Binary STL stores single precision: a larger coordinate would become infinite.
        if let Some(index) = grid.iter().position(|x| x.abs() > f64::from(f32::MAX)) {
            return Err(MeshError::OutOfRange {
                index,
                value: grid.as_slice()[index],
            });
        }
    }
    Ok(match format {
        MeshFormat::Stl => to_stl(&mesh),
        MeshFormat::Obj => to_obj(&mesh).into_bytes(),
        MeshFormat::PlyAscii => to_ply_ascii(&mesh).into_bytes(),
        MeshFormat::PlyBinary => to_ply_binary(&mesh),
    })
}

/// Writes `grid` as a mesh to `path`, in the format of its extension, atomically.
pub fn write(grid: &PointGrid<f64>, path: &Path) -> Result<(), MeshError> {
    let bytes = encode(grid, MeshFormat::from_path(path)?)?;
    crate::write_atomic(path, &bytes).map_err(|e| MeshError::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orientation_follows_xu_cross_xv() {
        // x(u, v) = (u, v, 0): x_u × x_v = +z, so every normal must point up.
        let grid = PointGrid::from_shape_fn((4, 3, 3), |(i, j, k)| [i as f64, j as f64, 0.0][k]);
        let mesh = triangulate(&grid).unwrap();
        assert_eq!(mesh.triangles.len(), 2 * 3 * 2);
        for &t in &mesh.triangles {
            let n = normal(&mesh, t);
            assert!(n[2] > 0.0 && n[0] == 0.0 && n[1] == 0.0);
        }
    }

    #[test]
    fn collapsed_edge_skips_degenerate_triangles() {
        // Row i = 0 collapses to one point (a triangular patch): one triangle of each first
        // cell has two equal vertices.
        let grid = PointGrid::from_shape_fn((3, 3, 3), |(i, j, k)| {
            let (u, v) = (i as f64 / 2.0, j as f64 / 2.0);
            [u, u * v, u * u][k]
        });
        let mesh = triangulate(&grid).unwrap();
        assert_eq!(mesh.skipped, 2);
        assert_eq!(mesh.triangles.len(), 6);
    }

    #[test]
    fn bad_grids() {
        assert!(matches!(
            triangulate(&PointGrid::from_elem((1, 5, 3), 0.0)),
            Err(MeshError::Shape { .. })
        ));
        assert!(matches!(
            triangulate(&PointGrid::from_elem((2, 2, 4), 0.0)),
            Err(MeshError::Shape { .. })
        ));
        let mut g = PointGrid::from_elem((2, 2, 3), 0.0);
        g[[1, 1, 2]] = f64::NAN;
        assert!(matches!(
            triangulate(&g),
            Err(MeshError::NonFinite { index: 11 })
        ));
    }
}
