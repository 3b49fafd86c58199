//! The Markdown this project writes (reports, `references/`), as HTML: the
//! subset it uses and no more. Blocks: ATX headings, paragraphs, pipe
//! tables, bullet and numbered lists (nested by indentation), fenced code,
//! an image alone on its line (handed to the caller, which inlines it).
//! Inline: `code`, **bold**, *emphasis* is left as text, [links](url).
//! Every character of the text is escaped; nothing is passed through raw.

/// `&`, `<`, `>`, `"` as entities.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for ch in s.chars() {
        match ch {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            _ => out.push(ch),
        }
    }
    out
}

/// An id for `text`: lower case, runs of anything but letters and digits as
/// one `-`.
pub fn slug(text: &str) -> String {
    let mut out = String::new();
    for ch in text.chars().flat_map(char::to_lowercase) {
        if ch.is_alphanumeric() {
            out.push(ch);
        } else if !out.ends_with('-') && !out.is_empty() {
            out.push('-');
        }
    }
    out.trim_end_matches('-').to_string()
}

/// One line of inline Markdown as HTML: code spans, bold, links.
pub fn inline(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while !rest.is_empty() {
        if let Some(after) = rest.strip_prefix('`') {
            if let Some(end) = after.find('`') {
                out.push_str(&format!("<code>{}</code>", escape(&after[..end])));
                rest = &after[end + 1..];
                continue;
            }
        }
        if let Some(after) = rest.strip_prefix("**") {
            if let Some(end) = after.find("**") {
                out.push_str(&format!("<strong>{}</strong>", inline(&after[..end])));
                rest = &after[end + 2..];
                continue;
            }
        }
        if let Some(after) = rest.strip_prefix('[') {
            if let Some((label, url, used)) = link(after) {
                out.push_str(&format!("<a href=\"{}\">{}</a>", escape(url), inline(label)));
                rest = &after[used..];
                continue;
            }
        }
        let ch = rest.chars().next().expect("not empty");
        out.push_str(&escape(&rest[..ch.len_utf8()]));
        rest = &rest[ch.len_utf8()..];
    }
    out
}

/// `label](url)` at the start of `s`: the label, the url and the bytes used.
fn link(s: &str) -> Option<(&str, &str, usize)> {
    let close = s.find("](")?;
    let end = s[close + 2..].find(')')? + close + 2;
    let (label, url) = (&s[..close], &s[close + 2..end]);
    (!label.contains('[') && !url.contains(' ')).then_some((label, url, end + 1))
}

/// An image alone on a line: `![caption](file)`.
pub fn image(line: &str) -> Option<(&str, &str)> {
    let l = line.trim();
    let (label, url, used) = link(l.strip_prefix("![")?)?;
    (used + 2 == l.len()).then_some((label, url))
}

/// The cells of a pipe-table row (`\|` is a literal bar).
pub fn cells(line: &str) -> Vec<String> {
    let l = line.trim();
    let l = l.strip_prefix('|').unwrap_or(l);
    let l = l.strip_suffix('|').filter(|s| !s.ends_with('\\')).unwrap_or(l);
    let mut out = vec![String::new()];
    let mut chars = l.chars().peekable();
    while let Some(ch) = chars.next() {
        match ch {
            '\\' if chars.peek() == Some(&'|') => {
                out.last_mut().expect("one cell").push('|');
                chars.next();
            }
            '|' => out.push(String::new()),
            _ => out.last_mut().expect("one cell").push(ch),
        }
    }
    out.into_iter().map(|c| c.trim().to_string()).collect()
}

fn is_separator(line: &str) -> bool {
    let c = cells(line);
    !c.is_empty() && c.iter().all(|c| !c.is_empty() && c.chars().all(|ch| matches!(ch, '-' | ':')))
}

/// A list item's marker: (indent, text after the marker, numbered).
fn item(line: &str) -> Option<(usize, &str, bool)> {
    let indent = line.len() - line.trim_start().len();
    let t = line.trim_start();
    if let Some(rest) = t.strip_prefix("- ").or_else(|| t.strip_prefix("* ")) {
        return Some((indent, rest, false));
    }
    let digits = t.chars().take_while(char::is_ascii_digit).count();
    (digits > 0).then(|| t[digits..].strip_prefix(". ").map(|rest| (indent, rest, true))).flatten()
}

fn starts_block(line: &str) -> bool {
    let t = line.trim_start();
    t.starts_with('#') || t.starts_with('|') || t.starts_with("```") || item(line).is_some() || image(line).is_some()
}

/// Markdown `text` as HTML; `img(caption, file)` gives the HTML of an image
/// alone on its line; headings get ids `prefix` + their slug.
pub fn to_html(text: &str, prefix: &str, img: &mut dyn FnMut(&str, &str) -> String) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i];
        let t = line.trim_start();
        if t.is_empty() {
            i += 1;
        } else if t.starts_with("```") {
            let end = (i + 1..lines.len()).find(|&k| lines[k].trim_start().starts_with("```")).unwrap_or(lines.len());
            let body: Vec<&str> = lines[i + 1..end].to_vec();
            out.push_str(&format!("<pre><code>{}</code></pre>\n", escape(&body.join("\n"))));
            i = end + 1;
        } else if t.starts_with('#') {
            let level = t.chars().take_while(|&c| c == '#').count().min(6);
            let title = t[level..].trim();
            // Reports' own headings sit below the page's title.
            let h = (level + 1).min(6);
            out.push_str(&format!("<h{h} id=\"{prefix}{}\">{}</h{h}>\n", slug(title), inline(title)));
            i += 1;
        } else if t.starts_with('|') {
            let end = (i..lines.len()).find(|&k| !lines[k].trim_start().starts_with('|')).unwrap_or(lines.len());
            out.push_str(&table(&lines[i..end]));
            i = end;
        } else if let Some((caption, file)) = image(line) {
            out.push_str(&img(caption, file));
            i += 1;
        } else if item(line).is_some() {
            let mut end = i + 1;
            while end < lines.len() {
                let l = lines[end];
                let blank_then_more =
                    l.trim().is_empty() && lines.get(end + 1).is_some_and(|n| item(n).is_some() || n.starts_with("  "));
                if item(l).is_some() || (!l.trim().is_empty() && l.starts_with(' ')) || blank_then_more {
                    end += 1;
                } else if !l.trim().is_empty() && !starts_block(l) {
                    // A lazy continuation of the item's paragraph.
                    end += 1;
                } else {
                    break;
                }
            }
            out.push_str(&list(&lines[i..end], prefix, img));
            i = end;
        } else {
            let mut end = i + 1;
            while end < lines.len() && !lines[end].trim().is_empty() && !starts_block(lines[end]) {
                end += 1;
            }
            let para: Vec<&str> = lines[i..end].iter().map(|l| l.trim()).collect();
            out.push_str(&format!("<p>{}</p>\n", inline(&para.join(" "))));
            i = end;
        }
    }
    out
}

/// A pipe table; without a separator line every row is a body row.
fn table(rows: &[&str]) -> String {
    let mut out = String::from("<table class=\"md\">\n");
    let head = rows.len() > 1 && is_separator(rows[1]);
    for (k, r) in rows.iter().enumerate() {
        if head && k == 1 {
            continue;
        }
        let tag = if head && k == 0 { "th" } else { "td" };
        let cells: String = cells(r).iter().map(|c| format!("<{tag}>{}</{tag}>", inline(c))).collect();
        out.push_str(&format!("<tr>{cells}</tr>\n"));
    }
    out.push_str("</table>\n");
    out
}

/// A list, nested by the items' indentation; an item's continuation lines
/// (and blocks indented under it) belong to it.
fn list(lines: &[&str], prefix: &str, img: &mut dyn FnMut(&str, &str) -> String) -> String {
    let Some((indent, _, numbered)) = lines.first().and_then(|l| item(l)) else { return String::new() };
    let tag = if numbered { "ol" } else { "ul" };
    let mut out = format!("<{tag}>\n");
    let mut k = 0;
    while k < lines.len() {
        let Some((_, text, _)) = item(lines[k]) else {
            k += 1;
            continue;
        };
        let mut end = k + 1;
        while end < lines.len() && item(lines[end]).is_none_or(|(ind, _, _)| ind > indent) {
            end += 1;
        }
        // The item's own text, then what is indented under it, de-indented.
        let mut body = vec![text.to_string()];
        let inner = indent + 2;
        for l in &lines[k + 1..end] {
            let cut = l.len() - l.trim_start().len();
            body.push(if cut >= inner { l[inner..].to_string() } else { l.trim_start().to_string() });
        }
        let html = to_html(&body.join("\n"), prefix, img);
        // A one-paragraph item is shown without its <p>.
        let html = match html.strip_prefix("<p>").and_then(|h| h.strip_suffix("</p>\n")) {
            Some(p) if !p.contains("<p>") => p.to_string(),
            _ => html,
        };
        out.push_str(&format!("<li>{html}</li>\n"));
        k = end;
    }
    out.push_str(&format!("</{tag}>\n"));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn html(md: &str) -> String {
        to_html(md, "", &mut |c, f| format!("[img {c} {f}]"))
    }

    #[test]
    fn inline_code_bold_links_and_escapes() {
        assert_eq!(
            inline("a `x<y` **b** [c](d.md#e) & <"),
            "a <code>x&lt;y</code> <strong>b</strong> <a href=\"d.md#e\">c</a> &amp; &lt;"
        );
    }

    #[test]
    fn tables_lists_headings_images() {
        let out =
            html("# T i\n\npara\nmore\n\n| a | b \\| c |\n|---|---|\n| 1 | 2 |\n\n- x\n  - y\n- z\n\n![cap](f.png)\n");
        assert!(out.contains("<h2 id=\"t-i\">T i</h2>"), "{out}");
        assert!(out.contains("<p>para more</p>"), "{out}");
        assert!(out.contains("<th>b | c</th>") && out.contains("<td>2</td>"), "{out}");
        assert!(out.contains("<li><p>x</p>\n<ul>\n<li>y</li>\n</ul>\n</li>") && out.contains("<li>z</li>"), "{out}");
        assert!(out.contains("[img cap f.png]"), "{out}");
    }

    #[test]
    fn slugs() {
        assert_eq!(slug("ACADS (1989) problem 1(a)"), "acads-1989-problem-1-a");
        assert_eq!(slug("Eq. 21 against the LEM (rows `slip/*`)"), "eq-21-against-the-lem-rows-slip");
    }
}
