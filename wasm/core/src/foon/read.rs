//! Reader for FOON subgraph text, in both public dialects:
//! plain (`O<TAB>tomato<TAB>1[<TAB>dish-class]`, `M<TAB>slice<TAB><0:10,0:20>`) and
//! indexed (`O448<TAB>tomato<TAB>0`, `S117<TAB>sliced`, `M79<TAB>slice<TAB>1:07<TAB>1:14`).
//! A malformed file is an error naming file, line, column and reason; no unit is ever dropped silently.

use crate::error::{ErrorCode, FoonError, Result};
use crate::foon::label::{normalize_label, normalize_word};
use crate::foon::model::{ObjectNode, State, StateArg};
use crate::limits;
use crate::vocab::taxonomy::{dish_class_name, dish_classes, is_separating_motion, is_utensil};
use smol_str::SmolStr;

/// A goal mark on an object line: the finished dish of the subgraph, with its dish class if given.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GoalMark {
    pub dish_class: Option<u32>,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParsedObject {
    pub node: ObjectNode,
    pub moves: bool,
    pub goal: Option<GoalMark>,
    pub line: usize,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParsedUnit {
    pub inputs: Vec<ParsedObject>,
    pub motion: String,
    /// Motion timestamps as written (`0:10-0:20`, `Assumed`, ...), kept for provenance only.
    pub times: Vec<String>,
    pub outputs: Vec<ParsedObject>,
    /// Line of the motion node.
    pub line: usize,
}

/// One subgraph file: a named sequence of functional units.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Subgraph {
    pub name: String,
    /// The recipe's title, from its first `# title: …` comment line.
    pub title: Option<String>,
    pub units: Vec<ParsedUnit>,
    /// Problems that did not stop the read, each with its place (e.g. a unit skipped because its
    /// motion has no outputs, as happens in FOON-111). Never empty when something was skipped.
    pub warnings: Vec<FoonError>,
}

/// Reads a file's bytes: checks size and UTF-8 first, then parses.
pub fn parse_bytes(name: &str, bytes: &[u8]) -> Result<Subgraph> {
    check_size(name, bytes.len())?;
    match std::str::from_utf8(bytes) {
        Ok(text) => parse_str(name, text),
        Err(e) => {
            let good = &bytes[..e.valid_up_to()];
            let line = good.iter().filter(|&&b| b == b'\n').count() + 1;
            let column = good.iter().rev().take_while(|&&b| b != b'\n').count() + 1;
            Err(FoonError::at(
                ErrorCode::InvalidUtf8,
                name,
                line,
                column,
                "bytes that are not UTF-8 text (save the file as UTF-8)",
            ))
        }
    }
}

fn check_size(name: &str, bytes: usize) -> Result<()> {
    let most = limits::MAX_FILE_BYTES;
    if bytes <= most {
        return Ok(());
    }
    let message = format!("file is {bytes} bytes; the limit is {most} bytes");
    let mut e = FoonError::new(ErrorCode::TooLarge, message);
    e.file = Some(name.to_string());
    Err(e)
}

/// Which block of the current unit the reader is filling.
#[derive(Default, PartialEq)]
enum Block {
    #[default]
    Inputs,
    Outputs,
}

/// An object line whose state lines are still being read: label, flag, goal mark, line, states.
type OpenObject = (SmolStr, bool, Option<GoalMark>, usize, Vec<State>);

#[derive(Default)]
struct UnitBuilder {
    inputs: Vec<ParsedObject>,
    motion: Option<(String, Vec<String>, usize)>,
    outputs: Vec<ParsedObject>,
    block: Block,
    /// States of the object being read, before it is closed into a node.
    open: Option<OpenObject>,
}

impl UnitBuilder {
    fn is_empty(&self) -> bool {
        self.inputs.is_empty()
            && self.motion.is_none()
            && self.outputs.is_empty()
            && self.open.is_none()
    }

    fn close_object(&mut self) {
        if let Some((label, moves, goal, line, states)) = self.open.take() {
            let object = ParsedObject {
                node: ObjectNode::new(label, states),
                moves,
                goal,
                line,
            };
            match self.block {
                Block::Inputs => self.inputs.push(object),
                Block::Outputs => self.outputs.push(object),
            }
        }
    }

    /// Closes the unit: `Ok(None)` when it must be skipped with a warning (no motion, no outputs, a cut
    /// that changes the food).
    fn finish(
        mut self,
        file: &str,
        line: usize,
        warnings: &mut Vec<FoonError>,
    ) -> Result<Option<ParsedUnit>> {
        self.close_object();
        let mut skip = |code, at, why: String| {
            let why = format!("{why}; unit skipped");
            warnings.push(FoonError::at(code, file, at, 1, why));
            Ok(None)
        };
        let Some((motion, times, motion_line)) = self.motion else {
            // FOON-111 has units whose motion line was never written: without a motion there is no
            // action to plan, so the unit is skipped and reported.
            let first = self.inputs.first().map(|o| o.line).unwrap_or(line);
            let why = format!(
                "functional unit has object lines but no motion line (M) before line {line}"
            );
            return skip(ErrorCode::BadMotion, first, why);
        };
        if self.outputs.is_empty() {
            // FOON-111 has such units; a unit that makes nothing cannot be planned with, so it is
            // skipped and reported rather than failing the whole knowledge base.
            let why = format!("motion '{motion}' has no output object after it");
            return skip(ErrorCode::UnitWithoutOutputs, motion_line, why);
        }
        if let Some((from, to)) = changed_food(&motion, &self.inputs, &self.outputs) {
            // FOON-111's potato soup peels an onion into a carrot: a slip of annotation, which planned
            // would turn the user's onion into a carrot nobody asked for
            let why = format!(
                "'{motion}' turns '{from}' into '{to}', but it does not change what a food is"
            );
            return skip(ErrorCode::BadMotion, motion_line, why);
        }
        Ok(Some(ParsedUnit {
            inputs: self.inputs,
            motion,
            times,
            outputs: self.outputs,
            line: motion_line,
        }))
    }
}

/// The food a separating motion (`taxonomy::is_separating_motion`) takes in and the other food it gives
/// out, when it has one of each; a food named in the other's name (bread and bread slice) is the same.
fn changed_food<'a>(
    motion: &str,
    inputs: &'a [ParsedObject],
    outputs: &'a [ParsedObject],
) -> Option<(&'a str, &'a str)> {
    if !is_separating_motion(motion) {
        return None;
    }
    let only_food = |objects: &'a [ParsedObject]| {
        let mut foods = objects
            .iter()
            .map(|o| o.node.label.as_str())
            .filter(|l| !is_utensil(l));
        let first = foods.next()?;
        foods.all(|l| l == first).then_some(first)
    };
    let (from, to) = (only_food(inputs)?, only_food(outputs)?);
    let within = |a: &str, b: &str| a.split(' ').all(|w| b.split(' ').any(|v| v == w));
    (!within(from, to) && !within(to, from)).then_some((from, to))
}

/// A line's tab-separated fields, trimmed, with their 1-based character columns; empty trailing fields
/// are dropped (FOON files often end lines with a stray tab).
fn fields(line: &str) -> Vec<(usize, &str)> {
    let mut out = Vec::new();
    let mut col = 1usize;
    for part in line.split('\t') {
        out.push((col, part.trim()));
        col += part.chars().count() + 1;
    }
    while out.last().is_some_and(|(_, f)| f.is_empty()) {
        out.pop();
    }
    out
}

/// The line type: `O`, `S` or `M`, optionally followed by an index (indexed dialect) and optionally
/// preceded by `!` (goal mark). Returns (kind, goal-mark).
fn line_kind(head: &str) -> Option<(char, bool)> {
    let marked = head.strip_prefix('!');
    let mut chars = marked.unwrap_or(head).chars();
    let kind = chars.next()?;
    if !matches!(kind, 'O' | 'S' | 'M') || !chars.all(|c| c.is_ascii_digit()) {
        return None;
    }
    Some((kind, marked.is_some()))
}

/// A label in its normal form.
fn label_of(raw: &str) -> SmolStr {
    SmolStr::from(normalize_label(raw))
}

/// Parses a state's argument: `[container]` or `{a,b,c}`; `None` when it names nothing (`[]`, `{ , }`),
/// which the caller reports as a warning.
fn state_arg(line: &Line, col: usize, text: &str) -> Result<Option<StateArg>> {
    let bad = |why: &str| {
        let message = format!("state argument '{text}': {why}");
        line.error(ErrorCode::BadBrackets, col, message)
    };
    let (open, close) = match text.chars().next() {
        Some('[') => ('[', ']'),
        Some('{') => ('{', '}'),
        _ => return Err(bad("must be [container] or {ingredients}")),
    };
    let Some(inner) = text.strip_prefix(open).and_then(|t| t.strip_suffix(close)) else {
        return Err(bad(&format!(
            "'{open}' is not closed by '{close}' at the end"
        )));
    };
    if inner.contains(['[', ']', '{', '}']) {
        return Err(bad("nested brackets"));
    }
    if open == '[' {
        let container = label_of(inner);
        if container.is_empty() {
            return Ok(None);
        }
        line.check_text(col, "container", &container)?;
        return Ok(Some(StateArg::Container(container)));
    }
    let mut list: Vec<SmolStr> = inner
        .split(',')
        .map(label_of)
        .filter(|s| !s.is_empty())
        .collect();
    for item in &list {
        line.check_text(col, "ingredient", item)?;
    }
    if list.is_empty() {
        return Ok(None);
    }
    list.sort();
    list.dedup();
    Ok(Some(StateArg::Ingredients(list)))
}

/// Index of the first object whose label already occurred earlier in the list.
fn repeated_label_at(objects: &[ParsedObject]) -> Option<usize> {
    let mut seen = rustc_hash::FxHashSet::default();
    objects
        .iter()
        .position(|o| !seen.insert(o.node.label.as_str()))
}

/// Lines ended by LF, CRLF or a lone CR (old Mac files), without their ends. A file with CR line ends
/// would otherwise be one long line, and one that starts with `//` would be read as a single separator.
fn lines(text: &str) -> impl Iterator<Item = &str> {
    let mut rest = Some(text);
    std::iter::from_fn(move || {
        let t = rest?;
        let Some(at) = t.find(['\n', '\r']) else {
            rest = None;
            return Some(t);
        };
        let end = if t[at..].starts_with("\r\n") {
            at + 2
        } else {
            at + 1
        };
        rest = Some(&t[end..]);
        Some(&t[..at])
    })
}

fn too_long(file: &str, line: usize, bytes: usize) -> FoonError {
    let limit = limits::MAX_LINE_BYTES;
    let message = format!("line is {bytes} bytes long; the limit is {limit}");
    FoonError::at(ErrorCode::TooLarge, file, line, 1, message)
}

fn too_many_units(file: &str, line: usize) -> FoonError {
    let most = limits::MAX_UNITS;
    let message = format!("more than {most} functional units in one file");
    FoonError::at(ErrorCode::TooLarge, file, line, 1, message)
}

/// One goal node marked with two different dish classes in a file is an error: the planner could not tell
/// which kind of dish it is. The same mark repeated is fine (it is one goal).
fn check_goal_classes(file: &str, units: &[ParsedUnit]) -> Result<()> {
    let mut marks: Vec<(usize, &ObjectNode, u32)> = units
        .iter()
        .flat_map(|u| u.inputs.iter().chain(u.outputs.iter()))
        .filter_map(|o| Some((o.line, &o.node, o.goal.as_ref()?.dish_class?)))
        .collect();
    marks.sort();
    let mut first: rustc_hash::FxHashMap<&ObjectNode, (usize, u32)> = Default::default();
    for (line, node, class) in marks {
        let (first_line, first_class) = *first.entry(node).or_insert((line, class));
        if first_class != class {
            let message = format!("goal node '{node}' is marked with dish class {class} here and with {first_class} on line {first_line}");
            return Err(FoonError::at(ErrorCode::BadNumber, file, line, 1, message));
        }
    }
    Ok(())
}

/// Reads one subgraph from text. Tolerates a BOM, CRLF line ends, trailing white space and empty files.
pub fn parse_str(name: &str, text: &str) -> Result<Subgraph> {
    check_size(name, text.len())?;
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut reader = Reader {
        name,
        ..Reader::default()
    };
    let mut last_line = 0;
    let mut title = None;
    for (index, raw) in lines(text).enumerate() {
        let line_no = index + 1;
        last_line = line_no;
        if reader.units.len() > limits::MAX_UNITS {
            return Err(too_many_units(name, line_no - 1));
        }
        if raw.len() > limits::MAX_LINE_BYTES {
            return Err(too_long(name, line_no, raw.len()));
        }
        let line = raw.trim_end_matches(['\r', ' ', '\t']);
        let trimmed = line.trim_start();
        if trimmed.is_empty() {
            continue;
        }
        if let Some(comment) = trimmed.strip_prefix('#') {
            if title.is_none() {
                title = title_of(comment);
            }
            continue;
        }
        if trimmed.starts_with("//") {
            if !reader.unit.is_empty() {
                reader.end_unit(line_no)?;
            }
            continue;
        }
        reader.line(&Line {
            file: name,
            no: line_no,
            f: &fields(line),
        })?;
    }
    let Reader {
        unit,
        mut units,
        mut warnings,
        ..
    } = reader;
    if !unit.is_empty() {
        units.extend(unit.finish(name, last_line, &mut warnings)?);
    }
    if units.len() > limits::MAX_UNITS {
        return Err(too_many_units(name, last_line));
    }
    check_goal_classes(name, &units)?;
    Ok(Subgraph {
        name: name.to_string(),
        title,
        units,
        warnings,
    })
}

/// One O, S or M line: its file, number and fields (with their columns).
struct Line<'l> {
    file: &'l str,
    no: usize,
    f: &'l [(usize, &'l str)],
}

impl<'l> Line<'l> {
    fn error(&self, code: ErrorCode, col: usize, message: impl Into<String>) -> FoonError {
        FoonError::at(code, self.file, self.no, col, message)
    }

    /// Field `i`, not empty, else a `MissingField` error naming `what`.
    fn field(&self, i: usize, what: &str) -> Result<(usize, &'l str)> {
        self.f
            .get(i)
            .copied()
            .filter(|(_, s)| !s.is_empty())
            .ok_or_else(|| {
                let col = self
                    .f
                    .last()
                    .map(|(c, s)| c + s.chars().count())
                    .unwrap_or(1);
                self.error(ErrorCode::MissingField, col, format!("missing {what}"))
            })
    }

    /// An error when `text` (a `what` in field `col`) is empty or too long.
    fn check_text(&self, col: usize, what: &str, text: &str) -> Result<()> {
        let most = limits::MAX_LABEL_CHARS;
        if text.is_empty() {
            return Err(self.error(ErrorCode::EmptyLabel, col, format!("empty {what}")));
        }
        if text.chars().count() > most {
            let message = format!("{what} is longer than {most} characters");
            return Err(self.error(ErrorCode::TooLarge, col, message));
        }
        Ok(())
    }

    /// An error when the line has more than `most` fields.
    fn at_most(&self, most: usize, what: &str) -> Result<()> {
        match self.f.get(most) {
            Some(&(col, _)) => Err(self.error(ErrorCode::UnknownLine, col, what)),
            None => Ok(()),
        }
    }
}

/// The units of one file as its lines are read.
#[derive(Default)]
struct Reader<'a> {
    name: &'a str,
    units: Vec<ParsedUnit>,
    warnings: Vec<FoonError>,
    unit: UnitBuilder,
}

impl Reader<'_> {
    /// Closes the unit being read (at `line_no`) and starts the next.
    fn end_unit(&mut self, line_no: usize) -> Result<()> {
        let unit = std::mem::take(&mut self.unit);
        self.units
            .extend(unit.finish(self.name, line_no, &mut self.warnings)?);
        Ok(())
    }

    fn line(&mut self, line: &Line) -> Result<()> {
        let (head_col, head) = line.f[0];
        let Some((kind, bang)) = line_kind(head) else {
            let shown: String = head.chars().take(20).collect();
            let message = format!("unknown line type '{shown}': expected O (object), S (state), M (motion), '#' or '//'");
            return Err(line.error(ErrorCode::UnknownLine, head_col, message));
        };
        match kind {
            'O' => self.object(line, bang),
            'S' => self.state(line, head_col),
            _ => self.motion(line, head_col),
        }
    }

    /// `O<TAB>label<TAB>flag[<TAB>dish class]`: opens an object (`!` marks a goal).
    fn object(&mut self, line: &Line, bang: bool) -> Result<()> {
        self.unit.close_object();
        if self.unit.motion.is_some() {
            self.unit.block = Block::Outputs;
        }
        let (lcol, raw_label) = line.field(1, "object label after 'O'")?;
        let label = label_of(raw_label);
        line.check_text(lcol, "object label", &label)?;
        let moves = object_flag(line)?;
        let goal = goal_mark(line, bang)?;
        line.at_most(4, "object line has more than four fields")?;
        self.unit.open = Some((label, moves, goal, line.no, Vec::new()));
        Ok(())
    }

    /// `S<TAB>state[<TAB>argument]`: a state of the open object.
    fn state(&mut self, line: &Line, head_col: usize) -> Result<()> {
        let Some(open) = self.unit.open.as_mut() else {
            let why = "state line with no object line (O) before it in this unit";
            return Err(line.error(ErrorCode::StateWithoutObject, head_col, why));
        };
        let (scol, raw_state) = line.field(1, "state name after 'S'")?;
        // Some files write the argument in the same field: `in [bowl]`.
        let (word, inline_arg) = match raw_state.find(['[', '{']) {
            Some(at) => (&raw_state[..at], Some(raw_state[at..].trim())),
            None => (raw_state, None),
        };
        let state_name = normalize_word(word);
        line.check_text(scol, "state name", &state_name)?;
        let (acol, arg_text) = match (inline_arg, line.f.get(2)) {
            (Some(a), None) => (scol, Some(a)),
            (None, Some((acol, a))) => (*acol, Some(*a)),
            (None, None) => (scol, None),
            (Some(_), Some((acol, _))) => {
                return Err(line.error(ErrorCode::BadBrackets, *acol, "state has two arguments"));
            }
        };
        let arg = arg_text
            .map(|text| state_arg(line, acol, text))
            .transpose()?;
        // `on []` occurs in FOON-111: keep the state, drop the empty argument, report it (the same
        // for `[ ]`, `{ , }` and an argument written in the state field)
        if arg == Some(None) {
            let why = format!("state '{state_name}' has an empty argument; it was left out");
            self.warnings
                .push(line.error(ErrorCode::EmptyLabel, acol, why));
        }
        line.at_most(3, "state line has more than three fields")?;
        open.4.push(State {
            name: state_name.into(),
            arg: arg.flatten(),
        });
        Ok(())
    }

    /// `M<TAB>motion[<TAB>times]`: the unit's motion; its inputs are the objects before it.
    fn motion(&mut self, line: &Line, head_col: usize) -> Result<()> {
        self.unit.close_object();
        let (mcol, raw_motion) = line.field(1, "motion label after 'M'")?;
        let motion = normalize_word(raw_motion);
        line.check_text(mcol, "motion label", &motion)?;
        if let Some((first, _, first_line)) = &self.unit.motion {
            // A missing '//' (FOON-111 has a few): the next unit's inputs start where an output
            // label repeats. Without such a repeat the split is ambiguous, so it is an error.
            let Some(split) = repeated_label_at(&self.unit.outputs) else {
                let message = format!("second motion line in one unit (the first, '{first}', is on line {first_line}); separate units with '//'");
                return Err(line.error(ErrorCode::BadMotion, head_col, message));
            };
            let first_line = *first_line;
            let next_inputs = self.unit.outputs.split_off(split);
            let message = format!("missing '//' before this line (the unit of line {first_line} has a second motion on line {}); a new unit was started here", line.no);
            let at = next_inputs[0].line;
            let warning = FoonError::at(ErrorCode::BadMotion, line.file, at, 1, message);
            self.warnings.push(warning);
            self.end_unit(line.no)?;
            self.unit.inputs = next_inputs;
        }
        if self.unit.inputs.is_empty() {
            let why = format!("motion '{motion}' has no input object before it");
            return Err(line.error(ErrorCode::MotionWithoutInputs, head_col, why));
        }
        let times = line.f[2..]
            .iter()
            .map(|(_, t)| t.trim_matches(['<', '>']).to_string())
            .filter(|t| !t.is_empty())
            .collect();
        self.unit.motion = Some((motion, times, line.no));
        Ok(())
    }
}

/// An object line's motion flag (FOON's; some files write it as "00").
fn object_flag(line: &Line) -> Result<bool> {
    match line.f.get(2).map(|(c, t)| (c, t.parse::<u8>())) {
        None | Some((_, Ok(0))) => Ok(false),
        Some((_, Ok(1))) => Ok(true),
        Some((c, _)) => {
            let why = format!("object flag must be 0 or 1, found '{}'", line.f[2].1);
            Err(line.error(ErrorCode::BadNumber, *c, why))
        }
    }
}

/// An object line's goal mark: a known dish class in its fourth field, or `O!` without one.
fn goal_mark(line: &Line, bang: bool) -> Result<Option<GoalMark>> {
    let Some(&(c, class)) = line.f.get(3) else {
        return Ok(bang.then_some(GoalMark { dish_class: None }));
    };
    match class.parse::<u32>() {
        Ok(n) if dish_class_name(n).is_some() => Ok(Some(GoalMark {
            dish_class: Some(n),
        })),
        Ok(n) => {
            let last = dish_classes().last().map_or(0, |d| d.index);
            let why = format!("dish class {n} is not a known dish class (0 to {last})");
            Err(line.error(ErrorCode::BadNumber, c, why))
        }
        Err(_) => {
            let why = format!("dish class of a goal node must be a number, found '{class}'");
            Err(line.error(ErrorCode::BadNumber, c, why))
        }
    }
}

/// The title of a `# title: Greek salad` comment (the text after `#`), if it is one.
fn title_of(comment: &str) -> Option<String> {
    let rest = comment.trim_start();
    let (key, title) = rest.split_at_checked(6)?;
    let title = title.trim();
    (key.eq_ignore_ascii_case("title:") && !title.is_empty()).then(|| title.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    const PLAIN: &str = "# a comment\n//\nO\ttomato\t1\nS\twhole\nO\tknife\t0\nS\tclean\nM\tslice\t<0:10,0:20>\nO\ttomato\t1\nS\tsliced\nS\ton\t[cutting board]\n//\n";

    #[test]
    fn reads_a_plain_unit() {
        let g = parse_str("a.txt", PLAIN).unwrap();
        assert_eq!(g.units.len(), 1);
        let u = &g.units[0];
        assert_eq!(u.motion, "slice");
        assert_eq!(u.times, vec!["0:10,0:20"]);
        assert_eq!(u.inputs.len(), 2);
        assert!(u.inputs[0].moves);
        assert_eq!(u.outputs[0].node.container(), Some("cutting board"));
        assert_eq!(u.outputs[0].line, 8);
    }

    #[test]
    fn reads_the_indexed_dialect_and_goal_marks() {
        let text = "//\r\nO448\tTomatoes\t0\r\nS117\tsliced\r\nM79\tslice\t1:07\t1:14\r\nO2\tsalad\t1\t15\r\nS23\tcontains\t{tomato, Onions}\r\n//\r\n";
        let g = parse_str("b.txt", text).unwrap();
        let u = &g.units[0];
        assert_eq!(u.inputs[0].node.label, "tomato");
        assert_eq!(u.times, vec!["1:07", "1:14"]);
        assert_eq!(
            u.outputs[0].goal,
            Some(GoalMark {
                dish_class: Some(15)
            })
        );
        assert_eq!(
            u.outputs[0].node.ingredients::<String>(),
            vec!["onion", "tomato"]
        );
    }

    #[test]
    fn tolerates_bom_trailing_space_and_empty_files() {
        assert_eq!(parse_str("e.txt", "").unwrap().units.len(), 0);
        assert_eq!(
            parse_str("e.txt", "\u{feff}# only a comment\n\n")
                .unwrap()
                .units
                .len(),
            0
        );
        let spaced = PLAIN.replace('\n', "  \t\r\n");
        assert_eq!(
            parse_str("s.txt", &format!("\u{feff}{spaced}")).unwrap(),
            parse_str("s.txt", PLAIN).unwrap()
        );
    }

    #[test]
    fn a_unit_without_a_final_separator_is_kept() {
        let text = PLAIN.trim_end_matches("//\n");
        assert_eq!(parse_str("t.txt", text).unwrap().units.len(), 1);
    }
}
