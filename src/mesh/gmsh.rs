//! gmsh MSH 4.1 reader (ASCII and binary), written by hand so that physical
//! group names (`$PhysicalNames`) and sparse node tags survive.
//!
//! # The format, as far as this reader uses it
//!
//! A file is a list of sections `$Name ... $EndName`. `$MeshFormat` comes first
//! and is always ASCII: `4.1 file-type data-size`, file-type 0 (ASCII) or 1
//! (binary); a binary file follows this line with the int `1` written in the
//! file's byte order. `$PhysicalNames` is always ASCII: `dim tag "name"` lines.
//! In `$Entities`, `$Nodes` and `$Elements` of a binary file every `int` is 4
//! bytes, every `size_t` is data-size bytes (4 or 8) and every `double` 8.
//!
//! ```text
//! $Entities  nPoints nCurves nSurfaces nVolumes (size_t)
//!            point:  tag(int) x y z (double) nPhys(size_t) phys(int)...
//!            other:  tag(int) min xyz, max xyz (double) nPhys(size_t) phys(int)...
//!                    nBounding(size_t) bounding(int)...
//! $Nodes     nBlocks nNodes minTag maxTag (size_t)
//!            block: dim tag parametric (int) n (size_t); n tags (size_t);
//!                   n * (x y z [u [v [w]]]) (double, u v w only if parametric)
//! $Elements  nBlocks nElements minTag maxTag (size_t)
//!            block: dim tag type (int) n (size_t); n * (tag node...) (size_t)
//! ```
//!
//! Elements of entities of dimension 3 (types 4 tetrahedron, 5 hexahedron, 6
//! prism) become [`Cell`]s in gmsh node order; elements of dimension 0-2 (15
//! point, 1 line, 2 triangle, 3 quadrangle) become [`Facet`]s of the physical
//! groups of their entity. Node tags may be sparse: nodes are numbered densely
//! in file order and their tags kept in [`Mesh::node_tags`]. Unknown sections are
//! skipped; partitioned meshes are rejected.
//!
//! The reader validates instead of trusting: header counts and tag ranges,
//! node references, duplicate tags, finite coordinates and, at the end, the
//! orientation of every cell ([`check_cell`]). Errors say where: `line N` in an
//! ASCII file, `byte N` in a binary one. No input makes it panic.

use std::borrow::Cow;
use std::collections::{BTreeMap, HashMap};
use std::fmt::Display;
use std::path::Path;
use std::process::Command;
use std::str::FromStr;

use super::shape::{check_cell, CellKind};
use super::{Cell, Facet, Mesh, PhysicalGroup};
use crate::error::{Error, MeshError};

/// Reads a gmsh MSH 4.1 file (ASCII or binary).
pub fn read_msh(path: &Path) -> crate::Result<Mesh> {
    let bytes = std::fs::read(path).map_err(|e| Error::io(path, e))?;
    Ok(parse_msh(&bytes)?)
}

/// Parses the bytes of a gmsh MSH 4.1 file (ASCII or binary).
pub fn parse_msh(bytes: &[u8]) -> Result<Mesh, MeshError> {
    let mut r = Reader { buf: bytes, pos: 0, binary: false, size_t: 8, big_endian: false };
    mesh_format(&mut r)?;
    let mut msh = Msh::default();
    while let Some((at, name)) = r.section()? {
        match name.as_str() {
            "MeshFormat" => return r.fail(at, "second $MeshFormat section"),
            "PhysicalNames" => physical_names(&mut r, &mut msh.names)?,
            "Entities" if msh.entities.is_some() => return r.fail(at, "second $Entities section"),
            "Entities" => msh.entities = Some(entities(&mut r)?),
            "Nodes" if msh.nodes.is_some() => return r.fail(at, "second $Nodes section"),
            "Nodes" => msh.nodes = Some(nodes(&mut r)?),
            "Elements" if msh.read_elements => return r.fail(at, "second $Elements section"),
            "Elements" => elements(&mut r, &mut msh, at)?,
            "PartitionedEntities" => return r.fail(at, "partitioned meshes are not supported"),
            _ => r.skip_section(at, &name)?,
        }
    }
    finish(msh, &r)
}

/// Everything read so far.
#[derive(Default)]
struct Msh {
    names: BTreeMap<(u8, i32), String>,
    /// Physical tags of each entity `(dim, tag)`.
    entities: Option<HashMap<(u8, i32), Vec<i32>>>,
    nodes: Option<Nodes>,
    read_elements: bool,
    cells: Vec<Cell>,
    /// Members of each physical group `(dim, tag)`: cells and facets.
    members: BTreeMap<(u8, i32), (Vec<usize>, Vec<Facet>)>,
}

struct Nodes {
    coords: Vec<[f64; 3]>,
    tags: Vec<u64>,
    index: HashMap<u64, usize>,
}

/// A cursor over the file. `binary` is set once `$MeshFormat` says so: the
/// data sections are then binary and locations are byte offsets.
struct Reader<'a> {
    buf: &'a [u8],
    pos: usize,
    binary: bool,
    size_t: usize,
    big_endian: bool,
}

impl<'a> Reader<'a> {
    fn location(&self, at: usize) -> String {
        if self.binary {
            format!("byte {at}")
        } else {
            let line = 1 + self.buf.iter().take(at).filter(|&&b| b == b'\n').count();
            format!("line {line}")
        }
    }

    fn fail<T>(&self, at: usize, reason: impl Into<String>) -> Result<T, MeshError> {
        Err(MeshError::Parse { location: self.location(at), reason: reason.into() })
    }

    /// The offset of the next datum (in ASCII, of the next token).
    fn mark(&mut self) -> usize {
        while !self.binary && self.buf.get(self.pos).is_some_and(u8::is_ascii_whitespace) {
            self.pos += 1;
        }
        self.pos
    }

    fn remaining(&self) -> usize {
        self.buf.len().saturating_sub(self.pos)
    }

    /// A capacity for `n` items of at least `bytes` bytes each (binary; 2 in
    /// ASCII), capped by what the input can still hold.
    fn cap(&self, n: usize, bytes: usize) -> usize {
        let per = if self.binary { bytes.max(1) } else { 2 };
        n.min(self.remaining() / per)
    }

    /// The next whitespace-delimited token and its offset, None at the end.
    fn token(&mut self) -> Option<(usize, &'a [u8])> {
        while self.buf.get(self.pos).is_some_and(u8::is_ascii_whitespace) {
            self.pos += 1;
        }
        let start = self.pos;
        while self.buf.get(self.pos).is_some_and(|b| !b.is_ascii_whitespace()) {
            self.pos += 1;
        }
        let token = self.buf.get(start..self.pos)?;
        (!token.is_empty()).then_some((start, token))
    }

    /// Parses the next ASCII token as a `T`.
    fn ascii<T: FromStr>(&mut self, what: &str) -> Result<T, MeshError> {
        let Some((at, token)) = self.token() else {
            return self.fail(self.pos, format!("unexpected end of file: expected {what}"));
        };
        if token.starts_with(b"$") {
            let text = excerpt(token);
            return self.fail(at, format!("expected {what}, found `{text}`: fewer entries than the header says"));
        }
        match std::str::from_utf8(token).ok().and_then(|s| s.parse().ok()) {
            Some(value) => Ok(value),
            None => self.fail(at, format!("expected {what}, found `{}`", excerpt(token))),
        }
    }

    fn bytes<const N: usize>(&mut self, what: &str) -> Result<[u8; N], MeshError> {
        let Some(slice) = self.buf.get(self.pos..self.pos.saturating_add(N)) else {
            return self.fail(self.pos, format!("unexpected end of file: expected {what}"));
        };
        let mut b = [0u8; N];
        b.copy_from_slice(slice);
        self.pos += N;
        Ok(b)
    }

    fn int(&mut self, what: &str) -> Result<i32, MeshError> {
        if !self.binary {
            return self.ascii(what);
        }
        let b = self.bytes::<4>(what)?;
        Ok(if self.big_endian { i32::from_be_bytes(b) } else { i32::from_le_bytes(b) })
    }

    fn size(&mut self, what: &str) -> Result<u64, MeshError> {
        if !self.binary {
            return self.ascii(what);
        }
        Ok(if self.size_t == 4 {
            let b = self.bytes::<4>(what)?;
            u64::from(if self.big_endian { u32::from_be_bytes(b) } else { u32::from_le_bytes(b) })
        } else {
            let b = self.bytes::<8>(what)?;
            if self.big_endian {
                u64::from_be_bytes(b)
            } else {
                u64::from_le_bytes(b)
            }
        })
    }

    fn count(&mut self, what: &str) -> Result<usize, MeshError> {
        let at = self.pos;
        let n = self.size(what)?;
        usize::try_from(n).map_or_else(|_| self.fail(at, format!("{what} {n} is too large")), Ok)
    }

    fn double(&mut self, what: &str) -> Result<f64, MeshError> {
        if !self.binary {
            return self.ascii(what);
        }
        let b = self.bytes::<8>(what)?;
        Ok(if self.big_endian { f64::from_be_bytes(b) } else { f64::from_le_bytes(b) })
    }

    /// Consumes the line end after an ASCII line that binary data follows.
    fn line_end(&mut self) -> Result<(), MeshError> {
        while self.buf.get(self.pos).is_some_and(|&b| b == b' ' || b == b'\t' || b == b'\r') {
            self.pos += 1;
        }
        if self.buf.get(self.pos) != Some(&b'\n') {
            return self.fail(self.pos, "expected the end of the line before binary data");
        }
        self.pos += 1;
        Ok(())
    }

    /// The next section header `$Name`: its offset and name, None at the end.
    fn section(&mut self) -> Result<Option<(usize, String)>, MeshError> {
        let Some((at, token)) = self.token() else { return Ok(None) };
        let text = excerpt(token);
        match text.strip_prefix('$') {
            Some(name) if !name.is_empty() && !name.starts_with("End") => {
                if self.binary && matches!(name, "Entities" | "Nodes" | "Elements") {
                    self.line_end()?;
                }
                Ok(Some((at, name.to_owned())))
            }
            _ => self.fail(at, format!("expected a section header such as `$Nodes`, found `{text}`")),
        }
    }

    fn expect_end(&mut self, name: &str) -> Result<(), MeshError> {
        let end = format!("$End{name}");
        match self.token() {
            Some((_, token)) if token == end.as_bytes() => Ok(()),
            Some((at, token)) => {
                let text = excerpt(token);
                self.fail(at, format!("expected `{end}`, found `{text}`: more entries than the header says"))
            }
            None => self.fail(self.pos, format!("unexpected end of file: expected `{end}`")),
        }
    }

    /// Skips an unknown section up to its `$EndName`.
    fn skip_section(&mut self, at: usize, name: &str) -> Result<(), MeshError> {
        let end = format!("$End{name}");
        let rest = self.buf.get(self.pos..).unwrap_or_default();
        match rest.windows(end.len()).position(|w| w == end.as_bytes()) {
            Some(i) => {
                self.pos += i + end.len();
                Ok(())
            }
            None => self.fail(at, format!("section ${name} has no `{end}`")),
        }
    }
}

/// A token as text for a message (at most 40 bytes of it).
fn excerpt(token: &[u8]) -> Cow<'_, str> {
    String::from_utf8_lossy(&token[..token.len().min(40)])
}

fn mesh_format(r: &mut Reader) -> Result<(), MeshError> {
    match r.token() {
        Some((_, b"$MeshFormat")) => {}
        Some((at, _)) => return r.fail(at, "not a gmsh MSH file: expected `$MeshFormat` first"),
        None => return r.fail(0, "empty file"),
    }
    let Some((_, version)) = r.token() else { return r.fail(r.pos, "unexpected end of file: expected the version") };
    let version = excerpt(version).into_owned();
    if version.parse::<f64>() != Ok(4.1) {
        return Err(MeshError::UnsupportedVersion { version });
    }
    let at = r.mark();
    let file_type: i32 = r.ascii("file-type")?;
    let data_size: usize = r.ascii("data-size")?;
    match file_type {
        0 => {}
        1 => {
            if data_size != 4 && data_size != 8 {
                return r.fail(at, format!("binary data-size {data_size} is not supported (need 4 or 8)"));
            }
            r.line_end()?;
            r.binary = true;
            r.size_t = data_size;
            let one = r.bytes::<4>("the endianness int")?;
            if i32::from_be_bytes(one) == 1 {
                r.big_endian = true;
            } else if i32::from_le_bytes(one) != 1 {
                return r.fail(r.pos - 4, "the endianness int is not 1 in either byte order");
            }
        }
        _ => return r.fail(at, format!("file-type {file_type} is neither 0 (ASCII) nor 1 (binary)")),
    }
    r.expect_end("MeshFormat")
}

/// `$PhysicalNames` (always ASCII): `dim tag "name"` lines.
fn physical_names(r: &mut Reader, names: &mut BTreeMap<(u8, i32), String>) -> Result<(), MeshError> {
    let n: usize = r.ascii("the number of physical names")?;
    for _ in 0..n {
        let at = r.mark();
        let dim: u8 = r.ascii("a physical group dimension")?;
        let tag: i32 = r.ascii("a physical tag")?;
        if dim > 3 {
            return r.fail(at, format!("physical group dimension {dim} is not 0-3"));
        }
        while r.buf.get(r.pos).is_some_and(|&b| b == b' ' || b == b'\t') {
            r.pos += 1;
        }
        let rest = r.buf.get(r.pos..).unwrap_or_default();
        let line = &rest[..rest.iter().position(|&b| b == b'\n').unwrap_or(rest.len())];
        let name = match line.iter().rposition(|&b| b == b'"') {
            Some(close) if close > 0 && line.first() == Some(&b'"') => &line[1..close],
            _ => return r.fail(r.pos, "expected a quoted physical name"),
        };
        r.pos += line.len();
        if names.insert((dim, tag), String::from_utf8_lossy(name).into_owned()).is_some() {
            return r.fail(at, format!("physical group {dim}:{tag} named twice"));
        }
    }
    r.expect_end("PhysicalNames")
}

/// `$Entities`: keeps the physical tags of every entity.
fn entities(r: &mut Reader) -> Result<HashMap<(u8, i32), Vec<i32>>, MeshError> {
    let mut counts = [0usize; 4];
    for (dim, n) in counts.iter_mut().enumerate() {
        *n = r.count(
            ["the number of points", "the number of curves", "the number of surfaces", "the number of volumes"][dim],
        )?;
    }
    let mut phys = HashMap::new();
    for (dim, &n) in counts.iter().enumerate() {
        for _ in 0..n {
            let at = r.mark();
            let tag = r.int("an entity tag")?;
            for _ in 0..if dim == 0 { 3 } else { 6 } {
                r.double("an entity coordinate")?;
            }
            let n_phys = r.count("the number of physical tags")?;
            let mut tags = Vec::with_capacity(r.cap(n_phys, 4));
            for _ in 0..n_phys {
                tags.push(r.int("a physical tag")?);
            }
            if dim > 0 {
                for _ in 0..r.count("the number of bounding entities")? {
                    r.int("a bounding entity tag")?;
                }
            }
            tags.sort_unstable();
            tags.dedup();
            if phys.insert((dim as u8, tag), tags).is_some() {
                return r.fail(at, format!("entity {dim}:{tag} defined twice"));
            }
        }
    }
    r.expect_end("Entities")?;
    Ok(phys)
}

/// `$Nodes`: coordinates in file order, tags and the tag -> index map.
fn nodes(r: &mut Reader) -> Result<Nodes, MeshError> {
    let at = r.mark();
    let n_blocks = r.count("numEntityBlocks")?;
    let n_nodes = r.count("numNodes")?;
    let min_tag = r.size("minNodeTag")?;
    let max_tag = r.size("maxNodeTag")?;
    let cap = r.cap(n_nodes, 32);
    let mut nodes =
        Nodes { coords: Vec::with_capacity(cap), tags: Vec::with_capacity(cap), index: HashMap::with_capacity(cap) };
    for _ in 0..n_blocks {
        let block = r.mark();
        let dim = r.int("an entity dimension")?;
        let _entity = r.int("an entity tag")?;
        let parametric = r.int("the parametric flag")?;
        let n = r.count("numNodesInBlock")?;
        if !(0..=3).contains(&dim) || !(0..=1).contains(&parametric) {
            return r.fail(block, format!("node block of entity dimension {dim}, parametric {parametric}"));
        }
        let extra = if parametric == 1 { dim } else { 0 };
        let first = nodes.tags.len();
        for _ in 0..n {
            let tag = r.size("a node tag")?;
            if nodes.index.insert(tag, nodes.tags.len()).is_some() {
                return Err(MeshError::DuplicateNode { node: tag });
            }
            nodes.tags.push(tag);
        }
        for &tag in &nodes.tags[first..] {
            let mut x = [0.0; 3];
            for c in &mut x {
                *c = r.double("a node coordinate")?;
            }
            for _ in 0..extra {
                r.double("a parametric coordinate")?;
            }
            if !x.iter().all(|c| c.is_finite()) {
                return Err(MeshError::NonFiniteNode { node: tag });
            }
            nodes.coords.push(x);
        }
    }
    check_header(r, at, "nodes", n_nodes, (min_tag, max_tag), &nodes.tags)?;
    r.expect_end("Nodes")?;
    Ok(nodes)
}

/// Checks a section's header count and tag range against what it held.
fn check_header(
    r: &Reader,
    at: usize,
    what: &str,
    n: usize,
    (min, max): (u64, u64),
    tags: &[u64],
) -> Result<(), MeshError> {
    if tags.len() != n {
        return r.fail(at, format!("the header says {n} {what}, the blocks hold {}", tags.len()));
    }
    let (lo, hi) = (tags.iter().min(), tags.iter().max());
    if let (Some(&lo), Some(&hi)) = (lo, hi) {
        if (lo, hi) != (min, max) {
            return r.fail(at, format!("the header says {what} tags {min}..={max}, the blocks hold {lo}..={hi}"));
        }
    }
    Ok(())
}

/// The dimension and node count of a supported gmsh element type.
fn element_shape(gmsh_type: i32) -> Option<(u8, usize)> {
    match gmsh_type {
        15 => Some((0, 1)),
        1 => Some((1, 2)),
        2 => Some((2, 3)),
        3 => Some((2, 4)),
        _ => CellKind::from_gmsh_type(gmsh_type).map(|k| (3, k.n_nodes())),
    }
}

/// `$Elements`: volume elements become cells, the others facets of their
/// entity's physical groups. Needs `$Entities` and `$Nodes` first (MSH 4.1
/// puts them first).
fn elements(r: &mut Reader, msh: &mut Msh, section: usize) -> Result<(), MeshError> {
    msh.read_elements = true;
    let (Some(entities), Some(nodes)) = (&msh.entities, &msh.nodes) else {
        return r.fail(section, "$Elements must come after $Entities and $Nodes");
    };
    for (&(dim, _), phys) in entities {
        for &p in phys {
            msh.members.entry((dim, p)).or_default();
        }
    }
    let at = r.mark();
    let n_blocks = r.count("numEntityBlocks")?;
    let n_elements = r.count("numElements")?;
    let min_tag = r.size("minElementTag")?;
    let max_tag = r.size("maxElementTag")?;
    let mut tags = Vec::with_capacity(r.cap(n_elements, 16));
    for _ in 0..n_blocks {
        let block = r.mark();
        let dim = r.int("an entity dimension")?;
        let entity = r.int("an entity tag")?;
        let gmsh_type = r.int("an element type")?;
        let n = r.count("numElementsInBlock")?;
        let Some((type_dim, n_nodes)) = element_shape(gmsh_type) else {
            if n == 0 {
                continue;
            }
            return Err(MeshError::UnsupportedElement { element: r.size("an element tag")?, gmsh_type });
        };
        if i32::from(type_dim) != dim {
            return r.fail(
                block,
                format!("element type {gmsh_type} (dimension {type_dim}) in an entity of dimension {dim}"),
            );
        }
        let Some(phys) = entities.get(&(type_dim, entity)) else {
            return r.fail(block, format!("entity {dim}:{entity} is not in $Entities"));
        };
        for _ in 0..n {
            let tag = r.size("an element tag")?;
            let mut idx = [0usize; 8];
            for slot in &mut idx[..n_nodes] {
                let node = r.size("a node tag")?;
                *slot = *nodes.index.get(&node).ok_or(MeshError::UnknownNode { element: tag, node })?;
            }
            tags.push(tag);
            if let Some(kind) = CellKind::from_gmsh_type(gmsh_type) {
                for &p in phys {
                    msh.members.entry((3, p)).or_default().0.push(msh.cells.len());
                }
                msh.cells.push(Cell { kind, nodes: idx, tag });
            } else {
                let facet = Facet { nodes: [idx[0], idx[1], idx[2], idx[3]], n: n_nodes as u8 };
                for &p in phys {
                    msh.members.entry((type_dim, p)).or_default().1.push(facet);
                }
            }
        }
    }
    check_header(r, at, "elements", n_elements, (min_tag, max_tag), &tags)?;
    r.expect_end("Elements")
}

/// Assembles the mesh and checks every cell's orientation.
fn finish(msh: Msh, r: &Reader) -> Result<Mesh, MeshError> {
    let Some(nodes) = msh.nodes else { return r.fail(r.buf.len(), "no $Nodes section") };
    if !msh.read_elements {
        return r.fail(r.buf.len(), "no $Elements section");
    }
    if msh.cells.is_empty() {
        return Err(MeshError::NoCells);
    }
    for cell in &msh.cells {
        let mut corners = [[0.0; 3]; 8];
        for (c, &n) in corners.iter_mut().zip(cell.corners()) {
            *c = nodes.coords[n];
        }
        check_cell(cell.kind, &corners[..cell.kind.n_nodes()]).map_err(|d| d.into_mesh_error(cell.tag))?;
    }
    let mut members = msh.members;
    for &key in msh.names.keys() {
        members.entry(key).or_default();
    }
    let groups = members
        .into_iter()
        .map(|((dim, tag), (cells, facets))| PhysicalGroup {
            dim,
            tag,
            name: msh.names.get(&(dim, tag)).cloned().unwrap_or_else(|| format!("{dim}:{tag}")),
            cells,
            facets,
        })
        .collect();
    Ok(Mesh { nodes: nodes.coords, node_tags: nodes.tags, cells: msh.cells, groups })
}

/// Whether `gmsh` runs from PATH.
pub fn gmsh_available() -> bool {
    Command::new("gmsh").arg("--version").output().is_ok_and(|o| o.status.success())
}

/// Meshes `geo` with gmsh into `msh` (MSH 4.1): `gmsh <geo> -3 -format msh41
/// -o <msh>`. The `.geo` may set further options itself.
pub fn regenerate(geo: &Path, msh: &Path) -> crate::Result<()> {
    // gmsh writes a temporary sibling, moved into place once it succeeded:
    // a killed gmsh leaves no torn mesh.
    let tmp = crate::atomic::partial_path(msh);
    let command = format!("gmsh {} -3 -format msh41 -o {}", geo.display(), msh.display());
    let output = Command::new("gmsh")
        .arg(geo)
        .args(["-3", "-format", "msh41", "-o"])
        .arg(&tmp)
        .output()
        .map_err(|e| Error::Gmsh(format!("cannot run `{command}` (is gmsh on PATH? `pip install gmsh`): {e}")))?;
    let text = format!("{}{}", String::from_utf8_lossy(&output.stdout), String::from_utf8_lossy(&output.stderr));
    // gmsh exits with status 0 after most errors (even a .geo syntax error),
    // so its `Error` lines count as failure too: show those, else the tail.
    let lines: Vec<&str> = text.lines().collect();
    let errors: Vec<&str> = lines.iter().copied().filter(|l| l.starts_with("Error")).collect();
    if !output.status.success() || !errors.is_empty() || !tmp.is_file() {
        let _ = std::fs::remove_file(&tmp);
        let shown = if errors.is_empty() { &lines[lines.len().saturating_sub(20)..] } else { &errors[..] };
        return Err(Error::Gmsh(format!("`{command}` failed ({}):\n{}", output.status, shown.join("\n"))));
    }
    crate::atomic::commit(&tmp, msh).map_err(|e| Error::io(msh, e))
}

/// None if `a` and `b` are the same mesh: same node tags and cells
/// (connectivity and tags), same groups (dim, tag, name, members), node
/// coordinates equal within `tol` times the size of `a`'s bounding box.
/// Otherwise says what differs first.
pub fn mesh_drift(a: &Mesh, b: &Mesh, tol: f64) -> Option<String> {
    fn differ<T: PartialEq + Display>(what: &str, x: T, y: T) -> Option<String> {
        (x != y).then(|| format!("{what}: {x} vs {y}"))
    }
    let counts = differ("node count", a.nodes.len(), b.nodes.len())
        .or_else(|| differ("cell count", a.cells.len(), b.cells.len()))
        .or_else(|| differ("group count", a.groups.len(), b.groups.len()));
    if counts.is_some() {
        return counts;
    }
    if let Some(i) = (0..a.nodes.len()).find(|&i| a.node_tags.get(i) != b.node_tags.get(i)) {
        return Some(format!("node {i}: tag {:?} vs {:?}", a.node_tags.get(i), b.node_tags.get(i)));
    }
    for (i, (ca, cb)) in a.cells.iter().zip(&b.cells).enumerate() {
        if ca.kind != cb.kind || ca.corners() != cb.corners() || ca.tag != cb.tag {
            return Some(format!(
                "cell {i}: {:?} {:?} (tag {}) vs {:?} {:?} (tag {})",
                ca.kind,
                ca.corners(),
                ca.tag,
                cb.kind,
                cb.corners(),
                cb.tag
            ));
        }
    }
    for (ga, gb) in a.groups.iter().zip(&b.groups) {
        let (ka, kb) = ((ga.dim, ga.tag, &ga.name), (gb.dim, gb.tag, &gb.name));
        if ka != kb {
            return Some(format!("group {ka:?} vs {kb:?}"));
        }
        let facets_equal =
            ga.facets.len() == gb.facets.len() && ga.facets.iter().zip(&gb.facets).all(|(x, y)| x.nodes() == y.nodes());
        if ga.cells != gb.cells || !facets_equal {
            return Some(format!("group {:?}: members differ", ga.name));
        }
    }
    let mut size: f64 = 0.0;
    for d in 0..3 {
        let (lo, hi) =
            a.nodes.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| (lo.min(x[d]), hi.max(x[d])));
        size = size.max(hi - lo);
    }
    for (i, (xa, xb)) in a.nodes.iter().zip(&b.nodes).enumerate() {
        let within = |d: usize| (xa[d] - xb[d]).abs() <= tol * size;
        if !(0..3).all(within) {
            let tag = a.node_tags.get(i).copied().unwrap_or_default();
            return Some(format!("node {i} (tag {tag}): {xa:?} vs {xb:?} (tolerance {:e} m)", tol * size));
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One unit hexahedron (element 2) with its bottom quadrangle (element 1).
    const HEX: &str = "$MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
2
2 2 \"bottom\"
3 1 \"rock\"
$EndPhysicalNames
$Entities
0 0 1 1
1 0 0 0 1 1 0 1 2 0
1 0 0 0 1 1 1 1 1 1 1
$EndEntities
$Nodes
1 8 1 8
3 1 0 8
1
2
3
4
5
6
7
8
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
$EndNodes
$Elements
2 2 1 2
2 1 3 1
1 1 4 3 2
3 1 5 1
2 1 2 3 4 5 6 7 8
$EndElements
";

    fn parse_edited(from: &str, to: &str) -> Result<Mesh, MeshError> {
        assert!(HEX.contains(from), "{from:?} not in the test mesh");
        parse_msh(HEX.replacen(from, to, 1).as_bytes())
    }

    fn parse_error(result: Result<Mesh, MeshError>) -> (String, String) {
        match result {
            Err(MeshError::Parse { location, reason }) => (location, reason),
            other => panic!("expected a parse error, got {other:?}"),
        }
    }

    #[test]
    fn unit_hexahedron_reads_with_its_groups() {
        let mesh = parse_msh(HEX.as_bytes()).unwrap();
        assert_eq!(mesh.nodes.len(), 8);
        assert_eq!(mesh.cells[0].kind, CellKind::Hex8);
        assert_eq!(mesh.cells[0].tag, 2);
        let corners: Vec<[f64; 3]> = mesh.cells[0].corners().iter().map(|&n| mesh.nodes[n]).collect();
        assert!((check_cell(CellKind::Hex8, &corners).unwrap() - 1.0).abs() < 1e-12);
        let groups: Vec<_> =
            mesh.groups.iter().map(|g| (g.dim, g.tag, g.name.as_str(), g.cells.len(), g.facets.len())).collect();
        assert_eq!(groups, [(2, 2, "bottom", 0, 1), (3, 1, "rock", 1, 0)]);
    }

    #[test]
    fn truncated_file_is_a_parse_error_at_its_end() {
        let cut = &HEX[..HEX.find("1 1 0\n0 1 0").unwrap()];
        let (location, reason) = parse_error(parse_msh(cut.as_bytes()));
        assert_eq!(location, format!("line {}", cut.lines().count() + 1));
        assert!(reason.contains("end of file"), "{reason}");
    }

    #[test]
    fn every_prefix_of_a_valid_file_fails_without_panicking() {
        for n in 0..HEX.len() - 1 {
            assert!(parse_msh(&HEX.as_bytes()[..n]).is_err(), "prefix of {n} bytes parsed");
        }
        let binary = include_bytes!("../../tests/fixtures/column-binary.msh");
        assert!(parse_msh(binary).is_ok());
        for n in 0..binary.len() - 1 {
            assert!(parse_msh(&binary[..n]).is_err(), "prefix of {n} bytes parsed");
        }
    }

    #[test]
    fn corrupted_bytes_never_panic() {
        let binary: &[u8] = include_bytes!("../../tests/fixtures/column-binary.msh");
        let ascii: &[u8] = include_bytes!("../../verification/cases/column/column.msh");
        let mut seed: u64 = 0x9e37_79b9_7f4a_7c15;
        for k in 0..4000 {
            let mut bytes = if k % 2 == 0 { binary.to_vec() } else { ascii.to_vec() };
            for _ in 0..4 {
                seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
                let i = (seed >> 33) as usize % bytes.len();
                bytes[i] = (seed >> 17) as u8;
            }
            let _ = parse_msh(&bytes);
        }
    }

    #[test]
    fn version_2_2_is_unsupported() {
        assert_eq!(parse_edited("4.1 0 8", "2.2 0 8"), Err(MeshError::UnsupportedVersion { version: "2.2".into() }));
    }

    #[test]
    fn unknown_element_type_names_the_element() {
        // Type 7 is a 5-node pyramid.
        assert_eq!(parse_edited("3 1 5 1", "3 1 7 1"), Err(MeshError::UnsupportedElement { element: 2, gmsh_type: 7 }));
    }

    #[test]
    fn missing_node_reference_names_element_and_node() {
        assert_eq!(
            parse_edited("2 1 2 3 4 5 6 7 8", "2 1 2 3 4 5 6 7 9"),
            Err(MeshError::UnknownNode { element: 2, node: 9 })
        );
    }

    #[test]
    fn duplicate_node_tag_is_rejected() {
        assert_eq!(parse_edited("7\n8\n", "7\n7\n"), Err(MeshError::DuplicateNode { node: 7 }));
    }

    #[test]
    fn flipped_hexahedron_is_inverted() {
        // Swapping corners 2 and 4 turns the bottom face inside out.
        match parse_edited("2 1 2 3 4 5 6 7 8", "2 1 4 3 2 5 6 7 8") {
            Err(MeshError::Inverted { element: 2, volume, .. }) => assert!(volume < 0.0),
            other => panic!("expected Inverted for element 2, got {other:?}"),
        }
    }

    #[test]
    fn nan_coordinate_names_the_node() {
        assert_eq!(parse_edited("\n1 1 1\n", "\n1 NaN 1\n"), Err(MeshError::NonFiniteNode { node: 7 }));
    }

    #[test]
    fn header_count_must_match_the_blocks() {
        let (location, reason) = parse_error(parse_edited("1 8 1 8", "1 9 1 9"));
        assert_eq!(location, "line 15");
        assert!(reason.contains("9 nodes"), "{reason}");
        let (location, reason) = parse_error(parse_edited("1 8 1 8", "2 8 1 8"));
        assert_eq!(location, "line 33");
        assert!(reason.contains("found `$EndNodes`: fewer entries"), "{reason}");
    }

    #[test]
    fn non_numeric_token_is_a_parse_error() {
        let (location, reason) = parse_error(parse_edited("1 0 0\n1 1 0", "1 O 0\n1 1 0"));
        assert_eq!(location, "line 26");
        assert!(reason.contains("`O`"), "{reason}");
    }

    #[test]
    fn a_mesh_of_facets_only_has_no_cells() {
        let only_quad = HEX.replacen("2 2 1 2", "1 1 1 1", 1).replacen("3 1 5 1\n2 1 2 3 4 5 6 7 8\n", "", 1);
        assert_eq!(parse_msh(only_quad.as_bytes()), Err(MeshError::NoCells));
    }

    #[test]
    fn drift_reports_the_first_difference() {
        let a = parse_msh(HEX.as_bytes()).unwrap();
        let mut b = a.clone();
        assert_eq!(mesh_drift(&a, &b, 0.0), None);
        b.nodes[3][1] += 1e-12;
        assert_eq!(mesh_drift(&a, &b, 1e-9), None);
        assert!(mesh_drift(&a, &b, 0.0).unwrap().starts_with("node 3 (tag 4)"));
        b.groups[0].name = "base".into();
        assert!(mesh_drift(&a, &b, 1e-9).unwrap().starts_with("group"));
    }
}
