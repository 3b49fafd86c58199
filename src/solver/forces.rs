//! Stage 1 of a step, the internal forces, in three parallel passes:
//! 1. every element writes `K_e u_e` (eq. 12) into its own slot;
//! 2. every spring writes its force on node `a` (eq. 15) into its own slot
//!    (and, where the dashpots are on, its dashpot force into another);
//! 3. every node gathers its contributions in the fixed order of
//!    [`Gather`](crate::model::Gather).
//!
//! No two threads write the same value and every sum has a fixed order, so
//! the result is bit for bit the same whatever the number of threads.

use rayon::prelude::*;

use crate::model::{Model, ELEMENT_SLOT};
use crate::physics::damping::spring_dashpot;
use crate::physics::element::element_force;
use crate::physics::joint::JointState;
use crate::physics::plastic::{
    add_pressure_force, add_stress_force, cell_strains, cell_volumetric_strain, deviatoric, plastic_element_force,
    PlasticCells, RockState, Volumetric,
};
use crate::physics::spring::{relative_displacement, spring_contact_force, SpringState};

/// Smallest number of items a rayon task takes (keeps small models cheap).
const MIN_LEN: usize = 256;

/// Every element writes its force into its slot by the fast path
/// `f_e = K_e u_e` (elastic elements, and plastic ones in phase 1, whose
/// `K_e` is their mixed stiffness).
pub fn element_forces(model: &Model, u: &[f64], f_elem: &mut [f64]) {
    let el = &model.elements;
    f_elem.par_chunks_mut(ELEMENT_SLOT).with_min_len(MIN_LEN / 4).enumerate().for_each(|(e, f_e)| {
        let nodes = el.corners(e);
        element_force(el.stiffness(e), nodes, u, &mut f_e[..3 * nodes.len()]);
    });
}

/// Failure phase with plastic blocks: an element whose material yields
/// integrates its tetrahedra ([`plastic_element_force`], advancing their
/// history in `rock`); the others take the fast path. Prisms and tetrahedra
/// share the volumetric strain of their mesh vertices
/// ([`Volumetric::Nodal`]), in five passes, each parallel with a fixed sum
/// order:
/// 1. each such cell's own volumetric strain `theta_e` (smoothed: and its
///    mean deviatoric strain `dev(eps_e)`);
/// 2. each vertex's average `J_a = sum_e w_e theta_e / sum_e w_e` over its
///    cells, `w_e = V_e / n_e` (smoothed: and the same average of
///    `dev(eps_e)`, then each cell's mean of its vertices' averages `d_e`);
/// 3. every element's force (a nodal cell uses `mean_(a in e) J_a` and
///    leaves its pressure force out; a smoothed one shifts its deviatoric
///    strain by `alpha (d_e - dev(eps_e))` and applies its own share of the
///    shift's force; a hexahedron whose armed
///    [`Screen`](crate::physics::plastic::Screen) holds takes its fast path
///    `K_e u_e - f_p`, and one whose full pass leaves every tetrahedron
///    elastic arms it);
/// 4. each vertex's mean stress `P_a = sum_e w_e p_e / sum_e w_e`
///    (smoothed: and of `alpha dev(sigma_e)`);
/// 5. each nodal cell's pressure force `V_e mean_(a in e) P_a g_c`, the
///    virtual work of step 2's average (Bonet & Burton's average nodal
///    pressure tetrahedron; FLAC's nodal mixed discretization), and
///    smoothed, the same of step 4's deviatoric average (docs/method.md
///    2.9b, "Stiff triangles").
pub fn element_forces_plastic(model: &Model, rock: &mut RockState, u: &[f64], f_elem: &mut [f64]) {
    let el = &model.elements;
    let cells = &model.plastic;
    let RockState {
        surface,
        history,
        volumetric,
        pressure,
        vertex_strain,
        vertex_pressure,
        screen,
        smoothing,
        cell_strain,
        used_strain,
        cell_stress,
        vertex_dev_strain,
        vertex_dev_stress,
        ..
    } = rock;
    let alpha = *smoothing;
    let surface = &*surface;
    let vertex_of = |e: usize| el.corners(e).iter().map(|&n| model.mesh_node[n as usize] as usize);
    let weight = |e: usize| el.volume[e] / el.corners(e).len() as f64;
    let vertex_mean = |values: &[f64], a: usize| vertex_average(cells, weight, a, |e| [values[e]])[0];
    let vertex_mean6 = |values: &[[f64; 6]], a: usize| vertex_average(cells, weight, a, |e| values[e]);
    let cell_mean6 = |values: &[[f64; 6]], e: usize| {
        let mut s = [0.0; 6];
        for a in vertex_of(e) {
            for i in 0..6 {
                s[i] += values[a][i];
            }
        }
        s.map(|x| x / el.corners(e).len() as f64)
    };
    let nodal = cells.any_nodal();
    let smoothed = nodal && alpha > 0.0;
    if smoothed {
        // One evaluation of each cell's strains gives both averages.
        volumetric
            .par_iter_mut()
            .zip(cell_strain.par_iter_mut())
            .with_min_len(MIN_LEN)
            .enumerate()
            .filter(|(e, _)| cells.nodal[*e])
            .for_each(|(e, (theta, m))| {
                let (v, mean) = cell_strains(cells.topology(el.kind[e]), cells.tets(e), el.corners(e), u);
                (*theta, *m) = (v, deviatoric(mean));
            });
    } else if nodal {
        volumetric.par_iter_mut().with_min_len(MIN_LEN).enumerate().filter(|(e, _)| cells.nodal[*e]).for_each(
            |(e, theta)| {
                *theta = cell_volumetric_strain(cells.topology(el.kind[e]), cells.tets(e), el.corners(e), u);
            },
        );
    }
    if nodal {
        let theta = &*volumetric;
        vertex_strain.par_iter_mut().with_min_len(MIN_LEN).enumerate().for_each(|(a, j)| *j = vertex_mean(theta, a));
    }
    if smoothed {
        let cs = &*cell_strain;
        vertex_dev_strain.par_iter_mut().with_min_len(MIN_LEN).enumerate().for_each(|(a, d)| *d = vertex_mean6(cs, a));
        let vd = &*vertex_dev_strain;
        used_strain
            .par_iter_mut()
            .with_min_len(MIN_LEN)
            .enumerate()
            .filter(|(e, _)| cells.nodal[*e])
            .for_each(|(e, m)| *m = cell_mean6(vd, e));
    }
    let vertex_strain = &*vertex_strain;
    let used_strain = &*used_strain;
    f_elem
        .par_chunks_mut(ELEMENT_SLOT)
        .zip(history.par_iter_mut())
        .zip(volumetric.par_iter_mut())
        .zip(pressure.par_iter_mut())
        .zip(screen.par_iter_mut())
        .zip(cell_stress.par_iter_mut())
        .with_min_len(MIN_LEN / 16)
        .enumerate()
        .for_each(|(e, (((((f_e, hist), theta), p), screen), cs))| {
            let nodes = el.corners(e);
            let f_e = &mut f_e[..3 * nodes.len()];
            let material = el.material[e] as usize;
            match &surface[material] {
                Some(_) if screen.holds(nodes, u) => screen.force(el.stiffness(e), nodes, u, f_e),
                Some(mc) => {
                    let mode = match cells.nodal[e] {
                        true => {
                            let j = vertex_of(e).map(|a| vertex_strain[a]).sum::<f64>() / nodes.len() as f64;
                            Volumetric::at_vertices(j, used_strain[e], alpha)
                        }
                        false => Volumetric::Cell,
                    };
                    let r = el.offset[e]..el.offset[e + 1];
                    let (topo, tets, lame) =
                        (cells.topology(el.kind[e]), cells.tets(e), model.materials[material].lame);
                    let pore = model.water.as_ref().map_or(0.0, |w| w.element_pressure[e]);
                    // A hexahedron's screen: its radius from the pass's own stresses.
                    let g = if cells.nodal[e] { &[][..] } else { cells.sensitivity(e) };
                    let step =
                        plastic_element_force(topo, tets, &el.grad[r], lame, mc, nodes, u, mode, pore, g, hist, f_e);
                    (*theta, *p, *cs) = (step.volumetric, step.pressure, step.deviatoric);
                    if step.radius > 0.0 {
                        screen.arm(el.stiffness(e), nodes, u, f_e, step.radius);
                    } else {
                        screen.radius2 = 0.0;
                    }
                }
                None => element_force(el.stiffness(e), nodes, u, f_e),
            }
        });
    if nodal {
        let pressure = &*pressure;
        vertex_pressure
            .par_iter_mut()
            .with_min_len(MIN_LEN)
            .enumerate()
            .for_each(|(a, q)| *q = vertex_mean(pressure, a));
        let vertex_pressure = &*vertex_pressure;
        if smoothed {
            let cs = &*cell_stress;
            vertex_dev_stress
                .par_iter_mut()
                .with_min_len(MIN_LEN)
                .enumerate()
                .for_each(|(a, d)| *d = vertex_mean6(cs, a));
        }
        let vds = &*vertex_dev_stress;
        f_elem
            .par_chunks_mut(ELEMENT_SLOT)
            .with_min_len(MIN_LEN)
            .enumerate()
            .filter(|(e, _)| cells.nodal[*e])
            .for_each(|(e, f_e)| {
                let nodes = el.corners(e);
                let mean = vertex_of(e).map(|a| vertex_pressure[a]).sum::<f64>() / nodes.len() as f64;
                let r = el.offset[e]..el.offset[e + 1];
                add_pressure_force(&el.grad[r.clone()], el.volume[e] * mean, &mut f_e[..3 * nodes.len()]);
                if smoothed {
                    add_stress_force(&el.grad[r], el.volume[e], cell_mean6(vds, e), &mut f_e[..3 * nodes.len()]);
                }
            });
    }
}

/// The average `sum_e w_e x_e / sum_e w_e` of `value` over the nodally
/// averaged cells at mesh vertex `a` (0 where there are none), in the
/// cells' fixed order.
fn vertex_average<const N: usize>(
    cells: &PlasticCells,
    weight: impl Fn(usize) -> f64,
    a: usize,
    value: impl Fn(usize) -> [f64; N],
) -> [f64; N] {
    let (mut s, mut w) = ([0.0; N], 0.0);
    for &e in cells.vertex(a) {
        let (e, x) = (e as usize, value(e as usize));
        for i in 0..N {
            s[i] += weight(e) * x[i];
        }
        w += weight(e);
    }
    if w > 0.0 {
        s.map(|x| x / w)
    } else {
        [0.0; N]
    }
}

/// Elastic springs (phase 1, or no breakable interface): eq. 15 only.
pub fn spring_forces(model: &Model, state: &SpringState, u: &[f64], f_spring: &mut [[f64; 3]]) {
    let sp = &model.springs;
    f_spring.par_iter_mut().with_min_len(MIN_LEN).enumerate().for_each(|(s, f)| {
        let d = relative_displacement(u, sp.a[s] as usize, sp.b[s] as usize);
        *f = spring_contact_force(sp.kn[s], sp.ks[s], sp.normal[s], d, state.slip[s], state.status[s]);
    });
}

/// The spring dashpots of a failure phase that has them
/// ([`crate::solver::has_dashpots`]): each spring's damping force on its
/// node `a` from the velocities `v` ([`spring_dashpot`] with `beta`) into
/// its slot of `out`.
pub struct Dashpots<'a> {
    pub v: &'a [f64],
    pub beta: f64,
    pub out: &'a mut [[f64; 3]],
}

/// Failure phase: breakable springs (a strength in `joints`) take their
/// force from their joint law (eq. 17-18 for Coulomb joints) and update their own slip and
/// status; the others stay elastic. With `dashpots`, their forces come from
/// the same pass, which reads each spring once.
pub fn spring_forces_with_failure(
    model: &Model,
    joints: &JointState,
    state: &mut SpringState,
    u: &[f64],
    dashpots: Option<Dashpots>,
    f_spring: &mut [[f64; 3]],
) {
    let sp = &model.springs;
    let force = |s: usize, slip: &mut _, status: &mut _| {
        let d = relative_displacement(u, sp.a[s] as usize, sp.b[s] as usize);
        joints.force(s, &sp.get(s), d, slip, status)
    };
    let springs = f_spring.par_iter_mut().zip(state.slip.par_iter_mut()).zip(state.status.par_iter_mut());
    match dashpots {
        None => springs.with_min_len(MIN_LEN).enumerate().for_each(|(s, ((f, slip), status))| {
            *f = force(s, slip, status);
        }),
        Some(Dashpots { v, beta, out }) => springs.zip(out.par_iter_mut()).with_min_len(MIN_LEN).enumerate().for_each(
            |(s, (((f, slip), status), f_d))| {
                *f = force(s, slip, status);
                let w = relative_displacement(v, sp.a[s] as usize, sp.b[s] as usize);
                *f_d = spring_dashpot(beta, sp.kn[s], sp.ks[s], sp.normal[s], w);
            },
        ),
    }
}

/// Adds node `i`'s spring forces to `sum`, in its gather order.
#[inline]
fn add_springs(model: &Model, f_spring: &[[f64; 3]], i: usize, sum: &mut [f64; 3]) {
    let g = &model.gather;
    for &end in &g.spring_end[g.spring_ptr[i] as usize..g.spring_ptr[i + 1] as usize] {
        let fs = f_spring[(end >> 1) as usize];
        let sign = if end & 1 == 1 { 1.0 } else { -1.0 };
        for d in 0..3 {
            sum[d] += sign * fs[d];
        }
    }
}

/// Node `i`'s internal force: its element slots, then its springs.
#[inline]
fn node_force(model: &Model, f_elem: &[f64], f_spring: &[[f64; 3]], i: usize) -> [f64; 3] {
    let g = &model.gather;
    let mut sum = [0.0; 3];
    for &slot in &g.elem_slot[g.elem_ptr[i] as usize..g.elem_ptr[i + 1] as usize] {
        let slot = slot as usize;
        for d in 0..3 {
            sum[d] += f_elem[slot + d];
        }
    }
    add_springs(model, f_spring, i, &mut sum);
    sum
}

pub fn gather(model: &Model, f_elem: &[f64], f_spring: &[[f64; 3]], f_int: &mut [f64]) {
    f_int.par_chunks_mut(3).with_min_len(MIN_LEN).enumerate().for_each(|(i, f)| {
        f.copy_from_slice(&node_force(model, f_elem, f_spring, i));
    });
}

/// [`gather`], and per node the sum of its springs' dashpot forces
/// `f_dash_spring` into `f_dash` in the same order, in one pass over the
/// nodes.
pub fn gather_with_dashpots(
    model: &Model,
    f_elem: &[f64],
    f_spring: &[[f64; 3]],
    f_dash_spring: &[[f64; 3]],
    f_int: &mut [f64],
    f_dash: &mut [f64],
) {
    f_int.par_chunks_mut(3).zip(f_dash.par_chunks_mut(3)).with_min_len(MIN_LEN).enumerate().for_each(
        |(i, (f, f_d))| {
            f.copy_from_slice(&node_force(model, f_elem, f_spring, i));
            let mut sum = [0.0; 3];
            add_springs(model, f_dash_spring, i, &mut sum);
            f_d.copy_from_slice(&sum);
        },
    );
}
