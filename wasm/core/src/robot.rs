//! What a plan asks of a robot (`docs/robot.md`): each motion's cost and success rate, from the project's
//! table `data/robot_motions.tsv` or the request's own figures, and who does each unit — the robot, or a
//! person for the `human_steps` least reliable units.

use crate::contract::plan::{Performer, Plan, RobotOptions, RobotUnit, RobotView};
use crate::error::{FoonError, Result};
use crate::vocab::taxonomy::data_lines;
use std::collections::BTreeMap;
use std::sync::OnceLock;

const MOTIONS_TSV: &str = include_str!("../data/robot_motions.tsv");

/// A motion's figures for a robot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MotionFigures {
    /// Effort and time, 1 = a pick-and-place.
    pub cost: f64,
    /// The chance, 0..1, that a robot carries it out.
    pub success_rate: f64,
}

/// The project's table, by motion; `"*"` is the row for a motion not listed.
fn table() -> &'static BTreeMap<String, MotionFigures> {
    static TABLE: OnceLock<BTreeMap<String, MotionFigures>> = OnceLock::new();
    TABLE.get_or_init(|| parse_table(MOTIONS_TSV))
}

fn parse_table(text: &str) -> BTreeMap<String, MotionFigures> {
    // the table is the project's own: its test checks that every row reads
    data_lines(text)
        .filter_map(|line| {
            let fields: Vec<&str> = line.split('\t').map(str::trim).collect();
            let cost = fields.get(1)?.parse().ok()?;
            let success_rate = fields.get(2)?.parse().ok()?;
            Some((fields[0].to_string(), MotionFigures { cost, success_rate }))
        })
        .collect()
}

/// The figures the request's options give each motion: its own figures first, then the table's.
pub struct Motions<'a> {
    options: &'a RobotOptions,
}

impl<'a> Motions<'a> {
    /// Checks the request's figures: costs not negative, success rates in (0, 1].
    pub fn new(options: &'a RobotOptions) -> Result<Motions<'a>> {
        for (motion, &cost) in &options.motion_costs {
            if !(cost.is_finite() && cost >= 0.0) {
                return Err(FoonError::bad_query(format!(
                    "motion cost of '{motion}' is {cost}: it must be a number, 0 or more"
                )));
            }
        }
        for (motion, &rate) in &options.success_rates {
            if !(rate > 0.0 && rate <= 1.0) {
                return Err(FoonError::bad_query(format!(
                    "success rate of '{motion}' is {rate}: it must be more than 0 and at most 1"
                )));
            }
        }
        Ok(Motions { options })
    }

    /// A motion's figures: the request's or the table's for the whole motion, else the sum of its words'
    /// costs and the product of their rates ("scoop and pour"), else the table's default row.
    pub fn figures(&self, motion: &str) -> MotionFigures {
        let motion = motion.trim_end_matches('*').trim();
        if let Some(f) = self.whole(motion) {
            return f;
        }
        let parts: Vec<MotionFigures> = motion
            .split(" and ")
            .map(|m| self.whole(m.trim()).unwrap_or_else(|| table()["*"]))
            .collect();
        MotionFigures {
            cost: parts.iter().map(|f| f.cost).sum(),
            success_rate: parts.iter().map(|f| f.success_rate).product(),
        }
    }

    fn whole(&self, motion: &str) -> Option<MotionFigures> {
        let listed = table().get(motion);
        let asked = |figures: &BTreeMap<String, f32>| figures.get(motion).map(|&x| f64::from(x));
        let cost = asked(&self.options.motion_costs).or(listed.map(|f| f.cost));
        let rate = asked(&self.options.success_rates).or(listed.map(|f| f.success_rate));
        let default = table()["*"];
        (cost.is_some() || rate.is_some()).then(|| MotionFigures {
            cost: cost.unwrap_or(default.cost),
            success_rate: rate.unwrap_or(default.success_rate),
        })
    }
}

/// The robot view of a finished plan: each unit's figures and performer, the `human_steps` least reliable
/// units (ties: the earlier unit) given to a person, and the totals of what the robot does.
pub fn robot_view(plan: &Plan, options: &RobotOptions, motions: &Motions) -> RobotView {
    let figures: Vec<MotionFigures> = plan
        .units
        .iter()
        .map(|u| motions.figures(&u.motion))
        .collect();
    // a stable sort: ties stay in unit order
    let mut by_rate: Vec<usize> = (0..figures.len()).collect();
    by_rate.sort_by(|&a, &b| figures[a].success_rate.total_cmp(&figures[b].success_rate));
    let mut human_units: Vec<usize> = by_rate.into_iter().take(options.human_steps).collect();
    human_units.sort_unstable();
    let units: Vec<RobotUnit> = figures
        .iter()
        .enumerate()
        .map(|(i, f)| RobotUnit {
            cost: round(f.cost),
            success_rate: round(f.success_rate),
            by: if human_units.contains(&i) {
                Performer::Human
            } else {
                Performer::Robot
            },
        })
        .collect();
    let robot = || {
        figures
            .iter()
            .enumerate()
            .filter(|(i, _)| !human_units.contains(i))
    };
    RobotView {
        mode: options.mode,
        cost: round(robot().map(|(_, f)| f.cost).sum()),
        success_rate: round(robot().map(|(_, f)| f.success_rate).product()),
        units,
        human_units,
    }
}

/// Figures to four decimals: estimates, printed without float noise.
fn round(x: f64) -> f64 {
    (x * 1e4).round() / 1e4
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_reads_whole_and_has_a_default_row() {
        let rows = data_lines(MOTIONS_TSV).count();
        assert_eq!(table().len(), rows, "every row reads");
        assert!(table().contains_key("*"));
        for (m, f) in table() {
            assert!(
                f.cost >= 0.0 && f.success_rate > 0.0 && f.success_rate <= 1.0,
                "{m}"
            );
        }
    }

    #[test]
    fn compound_motions_add_costs_and_multiply_rates_and_requests_override() {
        let mut options = RobotOptions::default();
        let m = Motions::new(&options).unwrap();
        let (scoop, pour) = (m.figures("scoop"), m.figures("pour"));
        let both = m.figures("scoop and pour*");
        assert_eq!(both.cost, scoop.cost + pour.cost);
        assert_eq!(both.success_rate, scoop.success_rate * pour.success_rate);
        assert_eq!(m.figures("juggle"), table()["*"]);
        options.motion_costs.insert("pour".into(), 9.0);
        let m = Motions::new(&options).unwrap();
        assert_eq!(m.figures("pour").cost, 9.0);
        assert_eq!(m.figures("pour").success_rate, pour.success_rate);
        options.success_rates.insert("pour".into(), 1.5);
        assert!(Motions::new(&options).is_err(), "a rate above 1 is refused");
    }
}
