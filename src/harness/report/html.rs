//! The validation report as one self-contained web page (`report.html`,
//! beside `report.md`): the run's header, a summary by status, the table
//! grouped by case family (the paper's cases first, in the paper's order),
//! each status coloured and filterable, each row linked to the section of
//! `references/` it cites and to the figure that supports it; the reason of
//! every row that differs or is not met, in the row; then the report's
//! sections with their figures inlined (base64), each captioned with what
//! to look for and the rows it supports; the cited sections of
//! `references/` at the end. Plain HTML and CSS: the filters are radio
//! buttons and CSS `:has()`, no script.

use std::fmt::Write;
use std::path::Path;

use super::citations::{Citation, References};
use super::figures::{data_uri, note, supports};
use super::header::RunHeader;
use super::markdown::{escape, inline, slug, to_html};
use super::{cells, Check, Kind, Status, Table};

/// A family of cases: the rows whose id starts with one of `prefixes`.
struct Family {
    title: &'static str,
    prefixes: &'static [&'static str],
}

/// The families in the page's order: the paper's cases first, as the paper
/// takes them (the elastic slope, its LEM, the slip circle, progressive
/// failure, Wulong), then the rest; a row no family claims goes to the last.
const FAMILIES: &[Family] = &[
    Family { title: "The paper: the elastic slope (Figs. 6-7)", prefixes: &["slope/"] },
    Family { title: "The paper: limit equilibrium of its slope", prefixes: &["lem/paper/"] },
    Family { title: "The paper: eq. 21 and K_i on the slip circle (Fig. 9)", prefixes: &["slip/"] },
    Family { title: "The paper: progressive failure of the slope (Fig. 10)", prefixes: &["slope-failure/"] },
    Family {
        title: "The paper: Wulong (Figs. 13-14)",
        prefixes: &["wulong/snapshot", "wulong/toe-first", "wulong/no-slide"],
    },
    Family { title: "The laterally confined column (analytic)", prefixes: &["column/", "study/"] },
    Family { title: "The stiff and extreme suite (analytic)", prefixes: &["extreme/"] },
    Family { title: "The FEM reference against scikit-fem", prefixes: &["fem/"] },
    Family { title: "Limit equilibrium: published slopes", prefixes: &["lem/"] },
    Family { title: "Eq. 21 on circles no face follows", prefixes: &["analysis/"] },
    Family { title: "The block on a plane and strength reduction", prefixes: &["block/", "srm/"] },
    Family { title: "Plastic blocks: the Mohr-Coulomb rock mass", prefixes: &["plastic/"] },
    Family { title: "Joint sets: plane, wedge and toppling", prefixes: &["joints/"] },
    Family { title: "Pore water", prefixes: &["water/", "wulong/wet-"] },
    Family { title: "Runout", prefixes: &["runout/"] },
    Family { title: "Ensembles", prefixes: &["ensemble/"] },
    Family { title: "The committed meshes", prefixes: &["meshes/"] },
    Family { title: "Performance goals", prefixes: &["perf/"] },
];
const OTHER: &str = "Other rows";

/// The family title of row `id`.
pub fn family(id: &str) -> &'static str {
    FAMILIES.iter().find(|f| f.prefixes.iter().any(|p| id.starts_with(p))).map_or(OTHER, |f| f.title)
}

/// A status as a CSS class and filter group: `ok`, `fail`, `met`,
/// `not-met`, `match`, `differs`, `skipped` (every failing status is `fail`).
pub fn status_class(s: Status) -> &'static str {
    match s {
        Status::Ok => "ok",
        Status::Met => "met",
        Status::NotMet => "not-met",
        Status::Match => "match",
        Status::Differs => "differs",
        Status::Skipped => "skipped",
        _ => "fail",
    }
}

/// What a page is made of.
pub struct Page<'a> {
    /// "cdem reproduce", "Validation report (cargo test)".
    pub title: &'a str,
    pub header: &'a RunHeader,
    pub table: &'a Table,
    /// The line under the summary (counts, failing, time).
    pub summary: String,
    /// The failing rows, one line each.
    pub failures: &'a [String],
    /// The report's Markdown after its table (sections, tables, figures as
    /// `![caption](file)`), figure files relative to `dir`.
    pub sections: &'a str,
    pub dir: &'a Path,
    /// The repository root (its `references/`).
    pub root: &'a Path,
}

/// The figures the sections show: (file as written, page id).
fn figure_files(sections: &str) -> Vec<String> {
    sections.lines().filter_map(super::markdown::image).map(|(_, f)| f.to_string()).collect()
}

fn figure_id(file: &str) -> String {
    format!("fig-{}", slug(file))
}

/// The page as HTML.
pub fn page(p: &Page) -> String {
    let refs = References::new(p.root);
    let figures = figure_files(p.sections);
    let rows: Vec<(&Check, Status, Option<Citation>)> =
        p.table.rows.iter().map(|(c, s)| (c, *s, refs.cite(&c.id, &c.source))).collect();
    let mut html = String::new();
    let _ = write!(
        html,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<meta name=\"viewport\" \
         content=\"width=device-width, initial-scale=1\">\n<title>{}</title>\n<style>\n{}</style>\n</head>\n<body>\n",
        escape(p.title),
        css()
    );
    html.push_str(&header(p));
    html.push_str(&summary(p, &rows));
    html.push_str(&table(&rows, &figures));
    html.push_str(&sections(p));
    html.push_str(&cited(&rows));
    html.push_str("</body>\n</html>\n");
    html
}

fn header(p: &Page) -> String {
    let h = p.header;
    let tree = match h.changed_files {
        Some(0) => "clean tree".to_string(),
        Some(n) => format!("dirty tree: {n} changed or untracked files"),
        None => "tree state unknown".to_string(),
    };
    format!(
        "<header>\n<h1>{}</h1>\n<dl class=\"facts\">\n<dt>commit</dt><dd><code>{}</code> ({tree})</dd>\n<dt>date</dt><dd>{}</dd>\n\
         <dt>command</dt><dd><code>{}</code></dd>\n<dt>threads</dt><dd>{} rayon threads, {} cores available</dd>\n</dl>\n</header>\n",
        escape(p.title),
        escape(&h.commit),
        escape(&h.date),
        escape(&h.command),
        h.threads,
        h.cores
    )
}

/// The filter radio buttons and the counts by status.
fn summary(p: &Page, rows: &[(&Check, Status, Option<Citation>)]) -> String {
    let mut out = String::from("<section id=\"summary\">\n<h2>Summary</h2>\n");
    let _ = writeln!(out, "<p class=\"counts\">{}</p>", escape(&p.summary));
    out.push_str("<div class=\"filters\" role=\"group\" aria-label=\"show rows\">\n");
    let count = |class: &str| rows.iter().filter(|r| status_class(r.1) == class).count();
    let groups = [
        ("all", "all rows", rows.len()),
        ("fail", "failing", count("fail")),
        ("not-met", "not met", count("not-met")),
        ("differs", "differs", count("differs")),
        ("skipped", "skipped", count("skipped")),
        ("ok", "ok", count("ok")),
        ("met", "met", count("met")),
        ("match", "match", count("match")),
    ];
    for (k, (class, label, n)) in groups.iter().enumerate() {
        let _ = writeln!(
            out,
            "<input type=\"radio\" name=\"show\" id=\"show-{class}\"{}><label for=\"show-{class}\" class=\"chip st-{class}\">\
             {label} <b>{n}</b></label>",
            if k == 0 { " checked" } else { "" }
        );
    }
    out.push_str("</div>\n");
    if !p.failures.is_empty() {
        out.push_str("<div class=\"failing\"><h3>Failing rows</h3>\n<ul>\n");
        for f in p.failures {
            let _ = writeln!(out, "<li>{}</li>", escape(f));
        }
        out.push_str("</ul></div>\n");
    }
    out.push_str(
        "<p class=\"legend\">Asserted rows are <span class=\"st-ok\">ok</span> within their tolerance or \
         <span class=\"st-fail\">FAIL</span>; reported rows <span class=\"st-met\">met</span> or \
         <span class=\"st-not-met\">not met</span> against a goal (never failing the run); compared rows \
         <span class=\"st-match\">match</span> or <span class=\"st-differs\">differ</span>; \
         <span class=\"st-skipped\">skipped</span> rows say why. The source column links to the section of \
         <code>references/</code> that states the reference (at the end of this page); a row that differs or is \
         not met shows the reason from there.</p>\n</section>\n",
    );
    out
}

/// The table, one `<tbody>` per family.
fn table(rows: &[(&Check, Status, Option<Citation>)], figures: &[String]) -> String {
    let mut out = String::from(
        "<section id=\"validation\">\n<h2>Validation</h2>\n<table class=\"validation\">\n<thead><tr><th>case</th>\
         <th>quantity</th><th>ours</th><th>reference</th><th>rel. error</th><th>tolerance / goal</th><th>source</th>\
         <th>time (s)</th><th>result</th></tr></thead>\n",
    );
    let mut titles: Vec<&str> = FAMILIES.iter().map(|f| f.title).collect();
    titles.push(OTHER);
    for title in titles {
        let members: Vec<_> = rows.iter().filter(|r| family(&r.0.id) == title).collect();
        if members.is_empty() {
            continue;
        }
        let classes: Vec<&str> = {
            let mut v: Vec<&str> = members.iter().map(|r| status_class(r.1)).collect();
            v.sort_unstable();
            v.dedup();
            v
        };
        let _ = writeln!(
            out,
            "<tbody class=\"family {}\" id=\"family-{}\">\n<tr class=\"family-head\"><th colspan=\"9\">{} <span class=\"n\">{} rows</span></th></tr>",
            classes.iter().map(|c| format!("has-{c}")).collect::<Vec<_>>().join(" "),
            slug(title),
            escape(title),
            members.len()
        );
        for (c, status, cite) in members {
            out.push_str(&row(c, *status, cite.as_ref(), figures));
        }
        out.push_str("</tbody>\n");
    }
    out.push_str("</table>\n</section>\n");
    out
}

fn row(c: &Check, status: Status, cite: Option<&Citation>, figures: &[String]) -> String {
    let [ours, reference, err, bound] = cells(c, status);
    let class = status_class(status);
    let source = match cite {
        Some(ci) => format!(
            "<a href=\"#{}\" title=\"{}\">{}</a>",
            ci.section.anchor(),
            escape(&format!("{} § {}", ci.section.file, ci.section.heading)),
            escape(&c.source)
        ),
        None => escape(&c.source),
    };
    let figure = figures
        .iter()
        .find(|f| note(f).is_some_and(|(n, star)| supports(n, &star, &c.id)))
        .map(|f| format!(" <a class=\"fig-link\" href=\"#{}\">figure</a>", figure_id(f)))
        .unwrap_or_default();
    let mut result = format!("<span class=\"status\">{}</span>", escape(status.label()));
    for extra in
        [c.defect.as_deref().unwrap_or(""), if let Kind::Skipped { reason } = &c.kind { reason } else { "" }, &c.note]
    {
        if !extra.is_empty() {
            let _ = write!(result, ": {}", escape(extra));
        }
    }
    if matches!(status, Status::Differs | Status::NotMet) {
        match cite.and_then(|ci| ci.reason.as_ref()) {
            Some(r) => {
                let _ = write!(
                    result,
                    "<div class=\"reason\"><b>Why</b> ({}): {}</div>",
                    escape(&cite.expect("cited").section.file),
                    inline(r)
                );
            }
            None => {
                let _ = write!(
                    result,
                    "<div class=\"reason missing\">No paragraph of {} names this row (`{}`).</div>",
                    escape(cite.map_or(c.source.as_str(), |ci| ci.section.file.as_str())),
                    escape(&c.id)
                );
            }
        }
    }
    format!(
        "<tr class=\"row st-{class}\" id=\"row-{}\" data-id=\"{}\"><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td>\
         <td>{source}{figure}</td><td>{:.2}</td><td class=\"result\">{result}</td></tr>\n",
        slug(&c.id),
        escape(&c.id),
        escape(&c.case),
        escape(&c.quantity),
        escape(&ours),
        escape(&reference),
        escape(&err),
        escape(&bound),
        c.seconds
    )
}

/// The report's sections, figures inlined with their notes.
fn sections(p: &Page) -> String {
    if p.sections.trim().is_empty() {
        return String::new();
    }
    let mut img = |caption: &str, file: &str| figure(p.dir, caption, file, p.table);
    format!("<section id=\"sections\">\n{}</section>\n", to_html(p.sections, "sec-", &mut img))
}

/// One figure: the image inlined, its caption, what to look for, its rows.
fn figure(dir: &Path, caption: &str, file: &str, table: &Table) -> String {
    let id = figure_id(file);
    let img = match data_uri(&dir.join(file)) {
        Ok(uri) => format!("<img src=\"{uri}\" alt=\"{}\">", escape(caption)),
        Err(e) => format!("<p class=\"reason missing\">{}: {}</p>", escape(file), escape(&e.to_string())),
    };
    let mut cap = format!("<b>{}</b> <span class=\"file\">({})</span>", inline(caption), escape(file));
    match note(file) {
        Some((n, star)) => {
            let _ = write!(cap, "<br>Look for: {}", escape(n.look_for));
            let links: Vec<String> = table
                .rows
                .iter()
                .filter(|(c, _)| supports(n, &star, &c.id))
                .map(|(c, s)| {
                    format!("<a class=\"st-{}\" href=\"#row-{}\">{}</a>", status_class(*s), slug(&c.id), escape(&c.id))
                })
                .collect();
            if !links.is_empty() {
                let _ = write!(cap, "<br>Supports: {}", links.join(", "));
            }
        }
        None => cap.push_str("<br>Supports no row of the table (a figure for the eye)."),
    }
    format!("<figure id=\"{id}\">{img}<figcaption>{cap}</figcaption></figure>\n")
}

/// The sections of `references/` the rows cite, each once, in the order of
/// first citation.
fn cited(rows: &[(&Check, Status, Option<Citation>)]) -> String {
    let mut seen = Vec::new();
    let mut out = String::from(
        "<section id=\"references\">\n<h2>Cited sections of references/</h2>\n<p>Each as the repository has it; \
         the rows link here.</p>\n",
    );
    for ci in rows.iter().filter_map(|r| r.2.as_ref()) {
        let anchor = ci.section.anchor();
        if seen.contains(&anchor) {
            continue;
        }
        seen.push(anchor.clone());
        let body = to_html(&ci.section.text(), &format!("{anchor}-"), &mut |c, f| {
            format!("<p>[figure {}: {}]</p>", escape(c), escape(f))
        });
        let _ = writeln!(
            out,
            "<details><summary>{} § {}</summary>\n<div class=\"refbody\" id=\"{anchor}\">{body}</div></details>",
            escape(&ci.section.file),
            inline(&ci.section.heading)
        );
    }
    out.push_str("</section>\n");
    out
}

/// The style sheet, and the filters: a checked radio button hides every
/// row of another status, and the families with none of its rows.
fn css() -> String {
    let mut css = String::from(
        "body{font:15px/1.45 system-ui,-apple-system,'Segoe UI',sans-serif;margin:0 auto;max-width:1500px;padding:0 \
         18px 40px;color:#1d2330;background:#fff}\n\
         h1{font-size:26px;margin:18px 0 6px}h2{font-size:21px;margin:26px 0 8px;border-bottom:1px solid #d8dde6}\n\
         h3{font-size:17px}code{font-size:90%;background:#f3f5f8;padding:0 3px;border-radius:3px}\n\
         dl.facts{display:grid;grid-template-columns:max-content 1fr;gap:2px 14px;margin:0}dl.facts dt{color:#5a6475}\n\
         dl.facts dd{margin:0;overflow-wrap:anywhere}\n\
         .filters{display:flex;flex-wrap:wrap;gap:6px;margin:8px 0}.filters input{position:absolute;opacity:0}\n\
         .chip{display:inline-block;padding:3px 11px;border-radius:14px;border:1px solid #c3cad6;cursor:pointer;\
         background:#f6f7f9}\n.filters input:checked+label{outline:2px solid #1d2330}\n\
         .filters input:focus-visible+label{outline:2px dashed #1d2330}\n\
         table.validation{border-collapse:collapse;width:100%;font-size:13px}\n\
         table.validation th,table.validation td{border-bottom:1px solid #e3e7ee;padding:3px 6px;vertical-align:top;\
         text-align:left}\ntable.validation thead th{position:sticky;top:0;background:#eef1f5;z-index:1}\n\
         tr.family-head th{background:#dfe6f0;font-size:14px;padding-top:8px}tr.family-head .n{font-weight:normal;\
         color:#5a6475;margin-left:8px}\ntd.result{min-width:14em}td.result .status{font-weight:600}\n\
         .reason{margin-top:4px;padding:4px 6px;background:#fffbe6;border-left:3px solid #d9a400;font-weight:normal}\n\
         .reason.missing{background:#fdecea;border-left-color:#c62828}\n\
         .st-ok{background:#e3f4e5}.st-met{background:#e6f2fb}.st-match{background:#e3f4e5}\n\
         .st-not-met{background:#fff1d6}.st-differs{background:#f7e6fa}.st-skipped{background:#eceff3;color:#4a5260}\n\
         .st-fail{background:#fbdada;color:#8a1010}\ntr.row.st-fail td{font-weight:600}\n\
         span.st-ok,span.st-met,span.st-match,span.st-not-met,span.st-differs,span.st-skipped,span.st-fail,\
         figcaption a{padding:0 4px;border-radius:3px}\n\
         .failing{background:#fbdada;padding:4px 12px;border-radius:6px}\n\
         figure{margin:18px 0;max-width:1100px}figure img{max-width:100%;height:auto;border:1px solid #e3e7ee}\n\
         figcaption{font-size:14px;color:#30384a}figcaption .file{color:#6b7486}\n\
         table.md{border-collapse:collapse;font-size:13px;margin:6px 0}table.md th,table.md td{border:1px solid \
         #dde2ea;padding:2px 6px}\n\
         details{margin:4px 0;border:1px solid #e3e7ee;border-radius:4px;padding:2px 8px}summary{cursor:pointer;\
         font-weight:600}\n.refbody{font-size:14px}pre{background:#f3f5f8;padding:6px;overflow-x:auto}\n\
         .refbody:target{outline:2px solid #d9a400}\n",
    );
    for class in ["fail", "not-met", "differs", "skipped", "ok", "met", "match"] {
        let _ = writeln!(
            css,
            "body:has(#show-{class}:checked) tr.row:not(.st-{class}),body:has(#show-{class}:checked) \
             tbody.family:not(.has-{class}){{display:none}}"
        );
    }
    css
}
