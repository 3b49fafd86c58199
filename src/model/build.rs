//! Building a [`Model`] from a mesh and its [`ModelSpec`], in named stages.

use std::collections::{HashMap, HashSet};

use super::spec::{JointMode, ModelSpec, PLANE_TOLERANCE};
use super::union_find::UnionFind;
use super::{Elements, Gather, Interface, Model};
use crate::error::{Error, ModelError};
use crate::mesh::adjacency::{face_key, face_nodes, FaceAdjacency, FaceKey};
use crate::mesh::perturb::perturb_nodes;
use crate::mesh::shape::{dot, norm, sub, CellDefect};
use crate::mesh::Mesh;
use crate::physics::element::{element_operators, pack_symmetric};
use crate::physics::material::{Material, MaterialLaw, YoungPoisson};
use crate::physics::plastic::PlasticCells;
use crate::physics::spring::Springs;

/// Builds the model: 1. perturb nodes, 2. classify interfaces, 3. make node
/// copies (merging across merged interfaces), 4. element operators and masses,
/// 5. springs on the other interfaces, 6. constraints, 7. gravity, 8. water.
pub fn build(mesh: &Mesh, spec: &ModelSpec) -> Result<Model, Error> {
    let adj = FaceAdjacency::build(mesh)?;
    let coords = perturbed_coordinates(mesh, spec, &adj)?;
    let (interfaces, face_interface) = classify_interfaces(mesh, spec, &adj)?;
    let interface_of = |key: &FaceKey| face_interface.get(key).copied().unwrap_or(0);

    // 3. Node copies: one per (cell, corner) slot, merged across merged faces.
    let mut slot_offset = Vec::with_capacity(mesh.cells.len() + 1);
    slot_offset.push(0);
    for c in &mesh.cells {
        slot_offset.push(slot_offset.last().unwrap() + c.kind.n_nodes());
    }
    let mut uf = UnionFind::new(*slot_offset.last().unwrap());
    let slot = |c: usize, mesh_node: usize| {
        let k = mesh.cells[c].corners().iter().position(|&n| n == mesh_node).expect("face node is a cell corner");
        slot_offset[c] + k
    };
    // A cell joined to a neighbour through a merged face is inside a larger
    // impermeable block (no pore pressure in it, stage 8).
    let mut in_block = vec![false; mesh.cells.len()];
    for s in &adj.shared {
        let nodes = face_nodes(mesh, s.cells[0], s.faces[0]);
        if interfaces[interface_of(&face_key(&nodes))].mode == JointMode::Merged {
            for &n in &nodes {
                uf.union(slot(s.cells[0], n), slot(s.cells[1], n));
            }
            in_block[s.cells[0]] = true;
            in_block[s.cells[1]] = true;
        }
    }
    let mut node_of_slot = vec![u32::MAX; uf.len()];
    let mut root_node: HashMap<usize, u32> = HashMap::new();
    let mut mesh_node = Vec::new();
    for (c, cell) in mesh.cells.iter().enumerate() {
        for (k, &n) in cell.corners().iter().enumerate() {
            let s = slot_offset[c] + k;
            let next = root_node.len() as u32;
            let id = *root_node.entry(uf.find(s)).or_insert(next);
            if id == next {
                mesh_node.push(n as u32);
            }
            node_of_slot[s] = id;
        }
    }
    let n_nodes = mesh_node.len();
    let x0: Vec<[f64; 3]> = mesh_node.iter().map(|&n| coords[n as usize]).collect();

    // 4. Elements.
    let materials_of_cell = cell_materials(mesh, spec)?;
    let materials = spec_materials(spec);
    let mut el = Elements::default();
    let mut plastic = PlasticCells::default();
    let mut mass = vec![0.0; n_nodes];
    el.offset.push(0);
    for (c, cell) in mesh.cells.iter().enumerate() {
        let corners: Vec<[f64; 3]> = cell.corners().iter().map(|&n| coords[n]).collect();
        let mat = materials_of_cell[c];
        let op = element_operators(cell.kind, &corners, &materials[mat as usize])
            .map_err(|d| Error::Mesh(d.into_mesh_error(cell.tag)))?;
        let ids: Vec<u32> = (0..cell.kind.n_nodes()).map(|k| node_of_slot[slot_offset[c] + k]).collect();
        for (k, &id) in ids.iter().enumerate() {
            mass[id as usize] += op.mass[k];
        }
        let m = &materials[mat as usize];
        plastic.push(cell.kind, &corners, (!m.law.condenses()).then_some(m.lame));
        el.kind.push(cell.kind);
        el.nodes.extend_from_slice(&ids);
        el.offset.push(el.nodes.len());
        el.k_offset.push(el.k.len());
        el.k.extend(pack_symmetric(&op.k, cell.kind.n_nodes()));
        el.grad.extend_from_slice(&op.grad);
        el.material.push(mat);
        el.volume.push(op.volume);
        el.tag.push(cell.tag);
    }
    plastic.link_vertices(mesh.nodes.len(), |e| mesh.cells[e].corners().iter().map(|&n| n as u32).collect());
    if let Some((i, &m)) = mass.iter().enumerate().find(|(_, &m)| !(m > 0.0)) {
        return Err(ModelError::NonPositiveMass { node: i, mass: m }.into());
    }

    // 5. Springs on every shared face that is not merged.
    let springs = make_springs(mesh, &adj, &coords, &interfaces, &face_interface, |c, n| node_of_slot[slot(c, n)]);

    // 6. Constraints: every copy of a fixed mesh node is fixed.
    let mesh_fixed = fixed_mesh_nodes(mesh, spec)?;
    let fixed = (0..3 * n_nodes).map(|k| mesh_fixed[3 * mesh_node[k / 3] as usize + k % 3]).collect();

    // 7. Gravity.
    let g = spec.gravity;
    let mut f_ext: Vec<f64> = (0..3 * n_nodes).map(|k| mass[k / 3] * g[k % 3]).collect();

    // 8. Water: pore pressure on the spring interfaces and outer faces below it.
    let water = match spec.water {
        None => None,
        Some(w) => {
            // The centroid of each element with a pore pressure (none inside a block).
            let centroids: Vec<Option<[f64; 3]>> = (0..el.len())
                .map(|e| {
                    let c = el.corners(e);
                    (!in_block[e])
                        .then(|| [0, 1, 2].map(|d| c.iter().map(|&n| x0[n as usize][d]).sum::<f64>() / c.len() as f64))
                })
                .collect();
            let node_of = |c: usize, n: usize| node_of_slot[slot(c, n)];
            let (f_w, model) =
                super::water::water_forces(w, mesh, &adj, &coords, &x0, &springs, &interfaces, node_of, &centroids)?;
            for (f, w) in f_ext.iter_mut().zip(&f_w) {
                *f += w;
            }
            Some(model)
        }
    };

    let gather = Gather::build(&el, &springs, n_nodes);
    Ok(Model {
        x0,
        mesh_node,
        mass,
        fixed,
        f_ext,
        gravity: spec.gravity,
        elements: el,
        plastic,
        springs,
        materials,
        interfaces,
        gather,
        mesh_coords: coords,
        water,
        smoothing: spec.smoothing,
    })
}

/// The scene's `[[material]]` sections as materials (in scene order).
pub fn spec_materials(spec: &ModelSpec) -> Vec<Material> {
    spec.material
        .iter()
        .map(|m| Material {
            lame: YoungPoisson { young: m.youngs_modulus, poisson: m.poisson_ratio }.into(),
            density: m.density,
            law: m.strength.map_or(MaterialLaw::LinearElastic, |s| MaterialLaw::MohrCoulomb(s.into())),
        })
        .collect()
}

/// Fixed components of the mesh nodes (`3 n + d`) from the scene's `[[boundary]]` groups.
pub fn fixed_mesh_nodes(mesh: &Mesh, spec: &ModelSpec) -> Result<Vec<bool>, Error> {
    let mut fixed = vec![false; 3 * mesh.nodes.len()];
    for (b, bc) in spec.boundary.iter().enumerate() {
        let g = mesh
            .groups
            .iter()
            .find(|g| g.name == bc.group && g.dim < 3)
            .ok_or_else(|| unknown_group(mesh, format!("boundary[{b}].group"), &bc.group, "surface"))?;
        for n in mesh.group_nodes(g) {
            for axis in &bc.fix {
                fixed[3 * n + axis.index()] = true;
            }
        }
    }
    Ok(fixed)
}

/// An unknown group, answered with the groups of that kind the mesh has.
pub fn unknown_group(mesh: &Mesh, key: String, group: &str, what: &str) -> Error {
    let dims: &[u8] = if what == "volume" { &[3] } else { &[0, 1, 2] };
    let names: Vec<String> =
        mesh.groups.iter().filter(|g| dims.contains(&g.dim)).map(|g| format!("{:?}", g.name)).collect();
    let available = if names.is_empty() { "none".to_string() } else { names.join(", ") };
    ModelError::UnknownGroup { key, group: group.to_string(), what: what.to_string(), available }.into()
}

/// The scene's node perturbation (shared with the FEM, so both see the same
/// coordinates); an inversion names the gmsh element.
pub fn perturbed_coordinates(mesh: &Mesh, spec: &ModelSpec, adj: &FaceAdjacency) -> Result<Vec<[f64; 3]>, Error> {
    let p = &spec.perturbation;
    let mut flat = Vec::new();
    for (list, names) in [("keep_flat", &p.keep_flat), ("keep_on", &p.keep_on)] {
        for (i, name) in names.iter().enumerate() {
            let key = format!("perturbation.{list}[{i}]");
            let g = mesh
                .groups
                .iter()
                .find(|g| &g.name == name && g.dim == 2)
                .ok_or_else(|| unknown_group(mesh, key.clone(), name, "surface"))?;
            if list == "keep_flat" {
                let (deviation, extent) = plane_deviation(mesh, g);
                if deviation > PLANE_TOLERANCE * extent {
                    return Err(ModelError::NotPlanar { key, group: name.clone(), deviation, extent }.into());
                }
            }
            flat.push(g);
        }
    }
    perturb_nodes(mesh, adj, p.ratio, p.seed, &flat).map_err(|(c, d)| {
        let (tet, volume) = match d {
            CellDefect::Inverted { tet, volume } | CellDefect::Degenerate { tet, volume } => (tet, volume),
        };
        ModelError::PerturbationInverts { element: mesh.cells[c].tag, tet, volume }.into()
    })
}

/// The largest distance of a surface group's nodes from its plane (through
/// the nodes' centroid, normal the area-weighted facet normal, facets
/// oriented alike), and the group's extent (largest distance from the
/// centroid), both in m.
fn plane_deviation(mesh: &Mesh, g: &crate::mesh::PhysicalGroup) -> (f64, f64) {
    let nodes = mesh.group_nodes(g);
    let m = nodes.len().max(1) as f64;
    let c = [0, 1, 2].map(|d| nodes.iter().map(|&i| mesh.nodes[i][d]).sum::<f64>() / m);
    let mut n = [0.0; 3];
    for f in g.facets.iter().filter(|f| f.n >= 3) {
        let p: Vec<[f64; 3]> = f.nodes().iter().map(|&i| mesh.nodes[i]).collect();
        let (fnorm, area) = crate::mesh::adjacency::polygon_normal_area(&p);
        let s = if dot(n, fnorm) < 0.0 { -area } else { area };
        n = [0, 1, 2].map(|d| n[d] + s * fnorm[d]);
    }
    let len = norm(n);
    let r = |i: usize| sub(mesh.nodes[i], c);
    let extent = nodes.iter().map(|&i| norm(r(i))).fold(0.0, f64::max);
    if len == 0.0 {
        return (0.0, extent);
    }
    let deviation = nodes.iter().map(|&i| (dot(r(i), n) / len).abs()).fold(0.0, f64::max);
    (deviation, extent)
}

/// Interface 0 is `[joints]`; each `[[interface]]` maps its facets' keys to its index.
fn classify_interfaces(
    mesh: &Mesh,
    spec: &ModelSpec,
    adj: &FaceAdjacency,
) -> Result<(Vec<Interface>, HashMap<FaceKey, usize>), Error> {
    let mut interfaces =
        vec![Interface { name: "joints".into(), mode: spec.joints.mode, props: spec.joints.props(spec.joints) }];
    let mut map = HashMap::new();
    // The internal faces (between two cells), once, if any interface is named.
    let internal: HashSet<FaceKey> = match spec.interface.is_empty() {
        true => HashSet::new(),
        false => adj.shared.iter().map(|s| face_key(&face_nodes(mesh, s.cells[0], s.faces[0]))).collect(),
    };
    for (i, s) in spec.interface.iter().enumerate() {
        let g = mesh
            .groups
            .iter()
            .find(|g| g.name == s.group && g.dim == 2)
            .ok_or_else(|| unknown_group(mesh, format!("interface[{i}].group"), &s.group, "surface"))?;
        let outer = g.facets.iter().filter(|f| !internal.contains(&face_key(f.nodes()))).count();
        if outer > 0 {
            return Err(ModelError::NotAnInterface {
                key: format!("interface[{i}].group"),
                group: s.group.clone(),
                outer,
                facets: g.facets.len(),
            }
            .into());
        }
        for f in &g.facets {
            map.insert(face_key(f.nodes()), i + 1);
        }
        interfaces.push(Interface { name: s.group.clone(), mode: s.mode, props: s.props(spec.joints) });
    }
    Ok((interfaces, map))
}

/// Material index of every cell from the scene's `[[material]]` volume groups.
pub fn cell_materials(mesh: &Mesh, spec: &ModelSpec) -> Result<Vec<u16>, Error> {
    let mut mat = vec![u16::MAX; mesh.cells.len()];
    for (i, m) in spec.material.iter().enumerate() {
        let g = mesh
            .groups
            .iter()
            .find(|g| g.name == m.group && g.dim == 3)
            .ok_or_else(|| unknown_group(mesh, format!("material[{i}].group"), &m.group, "volume"))?;
        for &c in &g.cells {
            mat[c] = i as u16;
        }
    }
    if let Some(c) = mat.iter().position(|&m| m == u16::MAX) {
        let names: Vec<String> = mesh
            .groups
            .iter()
            .filter(|g| g.dim == 3 && g.cells.contains(&c))
            .map(|g| format!("{:?}", g.name))
            .collect();
        let groups = if names.is_empty() {
            " (none: the element is in no volume group)".into()
        } else {
            format!(" {}", names.join(", "))
        };
        return Err(ModelError::NoMaterial { element: mesh.cells[c].tag, groups }.into());
    }
    Ok(mat)
}

/// One spring per coincident node pair of every non-merged shared face. The
/// node's area is half of each face triangle `(a, next, F)` and `(prev, a, F)`
/// (`F` the face centroid); its normal is their area-weighted normal, out of
/// the first cell.
fn make_springs(
    mesh: &Mesh,
    adj: &FaceAdjacency,
    coords: &[[f64; 3]],
    interfaces: &[Interface],
    face_interface: &HashMap<FaceKey, usize>,
    node_of: impl Fn(usize, usize) -> u32,
) -> Springs {
    let mut sp = Springs::default();
    for s in &adj.shared {
        let nodes = face_nodes(mesh, s.cells[0], s.faces[0]);
        let iface = face_interface.get(&face_key(&nodes)).copied().unwrap_or(0);
        if interfaces[iface].mode == JointMode::Merged {
            continue;
        }
        let p: Vec<[f64; 3]> = nodes.iter().map(|&n| coords[n]).collect();
        for (k, area, normal) in crate::mesh::adjacency::corner_shares(&p) {
            let (a_id, b_id) = (node_of(s.cells[0], nodes[k]), node_of(s.cells[1], nodes[k]));
            if a_id == b_id {
                continue; // already joined through a merged interface
            }
            let (kn, ks) = interfaces[iface].props.stiffness(area);
            sp.a.push(a_id);
            sp.b.push(b_id);
            sp.normal.push(normal);
            sp.area.push(area);
            sp.kn.push(kn);
            sp.ks.push(ks);
            sp.interface.push(iface as u16);
        }
    }
    sp
}
