//! The figures of a report page: what to look for in each and which rows of
//! the table it supports (the catalogue, by file name), and the image
//! itself inlined as a `data:` URI, so that the page is one file.

use std::path::Path;

/// What a figure shows and which rows it supports. `file` may hold one `*`
/// (a part of the name); a `*` in `rows` stands for the same part. A row
/// pattern ending in `/` covers every row id it starts.
#[derive(Debug, Clone, Copy)]
pub struct FigureNote {
    pub file: &'static str,
    pub look_for: &'static str,
    pub rows: &'static [&'static str],
}

const SLOPE: &[&str] = &["slope/"];
const SLIP: &[&str] = &["slip/"];
const WULONG_DRY: &[&str] = &["wulong/snapshot", "wulong/toe-first", "wulong/no-slide"];
const STUDY: &[&str] = &["study/"];

/// The figures `cdem reproduce` and the tests write.
pub const FIGURES: &[FigureNote] = &[
    FigureNote {
        file: "fig6-szz.png",
        look_for: "the vertical stress growing with depth in bands that follow the ground surface, CDEM above and the \
                   FEM on the same perturbed mesh below, band for band; the most compressive value at the base \
                   (the paper: -7.89e5 Pa).",
        rows: SLOPE,
    },
    FigureNote {
        file: "fig7-uz.png",
        look_for: "the settlement largest under the crest and falling to zero at the fixed base, CDEM and FEM alike \
                   (the paper: at most 4.18 cm).",
        rows: SLOPE,
    },
    FigureNote {
        file: "fig6-szz-diff.png",
        look_for: "CDEM minus FEM per element on a scale centred on zero: differences small against the stress \
                   itself (the note gives the largest as a percentage), without a pattern that would point to the \
                   joints' compliance.",
        rows: &["slope/cdem-vs-fem/"],
    },
    FigureNote {
        file: "fig7-uz-diff.png",
        look_for: "CDEM minus FEM of u_z per element, centred on zero: the springs' compliance adds settlement, so \
                   a one-signed field is expected; its size against u_z is the row's error.",
        rows: &["slope/cdem-vs-fem/"],
    },
    FigureNote {
        file: "history-slope.png",
        look_for: "dynamic relaxation's unbalanced-force ratio falling to the tolerance while the kinetic energy \
                   decays, and PCG reaching the same ratio in far fewer iterations (why phase 1 is PCG).",
        rows: &["slope/", "perf/dr-over-fem", "perf/pcg-over-fem"],
    },
    FigureNote {
        file: "fig9.png",
        look_for: "K_i along the LEM critical circle from the CDEM springs and the FEM stresses; the K_i < 1 zones \
                   shaded and lettered from the toe; the strip gives our sign segments against the paper's \
                   ab -, bc +, cd -, de + (the row that differs).",
        rows: SLIP,
    },
    FigureNote {
        file: "fig9-*.png",
        look_for: "K_i along the slip surface (the test's drawing of Fig. 9): where it crosses 1 and where its sign \
                   changes, against the paper's ab -, bc +, cd -, de +.",
        rows: SLIP,
    },
    FigureNote {
        file: "fig10-stages.png",
        look_for: "where the failed joints appear first (red: open, black: slipped), in the K_i < 1 zones near the \
                   toe, and how they spread along the circle until the mass above it slides.",
        rows: &["slope-failure/"],
    },
    FigureNote {
        file: "fig13-mesh.png",
        look_for: "Wulong's section as meshed: the layers and the joints the failure can follow.",
        rows: WULONG_DRY,
    },
    FigureNote {
        file: "fig14-stages.png",
        look_for: "the cracks opening at the toe first and later ones higher up (as observed in 2000-2001), and no \
                   global slide of the dry slope.",
        rows: WULONG_DRY,
    },
    FigureNote {
        file: "fig14-*.png",
        look_for: "Wulong's displacement at one stage of phase 2 (the test's drawing of Fig. 14): the toe moving \
                   first.",
        rows: WULONG_DRY,
    },
    FigureNote {
        file: "study/study-fs.png",
        look_for: "each plastic slope's factor of safety on three meshes (references/srm.md's measured figures, not \
                   this run's) falling onto its extrapolation from above: the committed meshes err on the unsafe \
                   side by 2.5 % (Griffiths & Lane) and 3.3 % (the paper slope), and halving the size costs 2 to 4 \
                   times the run time.",
        rows: &["fserror/gl1/*", "plastic/gl1-hex-srm", "plastic/paper-slope-srm"],
    },
    FigureNote {
        file: "study/study-*.png",
        look_for: "the error falling as the mesh is refined or the tolerance tightened, against what each costs in \
                   seconds: the cheapest setting for a given error.",
        rows: STUDY,
    },
    FigureNote {
        file: "joints/*-kinematics/stereonet.png",
        look_for: "the poles and great circles of the joint sets and the slope face (equal area, lower \
                   hemisphere), and the Markland tests' verdict on the modes the strength reduction then checks.",
        rows: &["joints/*-srm"],
    },
    FigureNote {
        file: "joints/*-mechanism.png",
        look_for: "the mechanism at the smallest unstable factor, in section and plan: the block moving on the \
                   planes the closed form assumes (one plane, two planes' line of intersection, or toppling \
                   columns).",
        rows: &["joints/*-srm"],
    },
    FigureNote {
        file: "water/wulong-fs-by-water.png",
        look_for: "the LEM's factor of safety falling as the water table rises, and the rise at which CDEM first \
                   slides beside it.",
        rows: &["wulong/wet-"],
    },
    FigureNote {
        file: "water/*-mechanism.png",
        look_for: "the mechanism at the smallest unstable factor with the water line in blue: the block that the \
                   closed form with water assumes is the one that moves.",
        rows: &["water/*-srm"],
    },
];

/// The note of `file` (a path relative to the report), and the part its `*` matched.
pub fn note(file: &str) -> Option<(&'static FigureNote, String)> {
    FIGURES.iter().find_map(|n| matched(n.file, file).map(|star| (n, star)))
}

fn matched(pattern: &str, file: &str) -> Option<String> {
    match pattern.split_once('*') {
        None => (pattern == file).then(String::new),
        Some((a, b)) => (file.len() >= a.len() + b.len() && file.starts_with(a) && file.ends_with(b))
            .then(|| file[a.len()..file.len() - b.len()].to_string()),
    }
}

/// Whether the figure of `note` (its `*` matched `star`) supports row `id`.
pub fn supports(note: &FigureNote, star: &str, id: &str) -> bool {
    note.rows.iter().any(|r| {
        let r = r.replace('*', star);
        if r.ends_with('/') || r.ends_with('-') {
            id.starts_with(&r)
        } else {
            id == r
        }
    })
}

/// The bytes of `path` as a `data:` URI (PNG, SVG or JPEG by extension).
pub fn data_uri(path: &Path) -> std::io::Result<String> {
    let bytes = std::fs::read(path)?;
    let mime = match path.extension().and_then(|e| e.to_str()) {
        Some("svg") => "image/svg+xml",
        Some("jpg" | "jpeg") => "image/jpeg",
        _ => "image/png",
    };
    Ok(format!("data:{mime};base64,{}", base64(&bytes)))
}

/// Standard base64 (RFC 4648, with padding).
pub fn base64(bytes: &[u8]) -> String {
    const ABC: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [chunk[0], *chunk.get(1).unwrap_or(&0), *chunk.get(2).unwrap_or(&0)];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(ABC[(n >> (18 - 6 * k) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_of_the_rfc_vectors() {
        for (plain, coded) in
            [("", ""), ("f", "Zg=="), ("fo", "Zm8="), ("foo", "Zm9v"), ("foob", "Zm9vYg=="), ("foobar", "Zm9vYmFy")]
        {
            assert_eq!(base64(plain.as_bytes()), coded);
        }
    }

    #[test]
    fn notes_match_by_pattern_and_support_rows() {
        let (n, star) = note("joints/wedge-general-mechanism.png").expect("a note");
        assert_eq!(star, "wedge-general");
        assert!(supports(n, &star, "joints/wedge-general-srm") && !supports(n, &star, "joints/wedge-srm"));
        let (n, star) = note("fig9.png").expect("a note");
        assert!(supports(n, &star, "slip/ki-signs-vs-paper"));
        assert!(note("unknown.png").is_none());
    }
}
