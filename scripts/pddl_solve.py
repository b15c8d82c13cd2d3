"""Solves foon-planner's PDDL exports with Fast Downward (docs/pddl.md).

    .venv/bin/python scripts/pddl_solve.py DOMAIN PROBLEM    # prints the plan found, one action a line
    .venv/bin/python scripts/pddl_solve.py --batch DIR       # every DIR/<name>/{domain,problem}.pddl, two at
                                                             # a time: one JSON object {name: {"plan": [...]}
                                                             # or {"error": "..."}} on stdout

Fast Downward is the build that the PyPI package up-fast-downward bundles (unified-planning's engine),
run through its own driver: its translator parses the files, and its optimal configuration (A* with
LM-cut) plans, so a plan found has no action it could do without. `npm run setup` makes the venv.
"""

import importlib.util
import json
import subprocess
import sys
import tempfile
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

# found without importing the package, which would load all of unified-planning
PACKAGE = importlib.util.find_spec("up_fast_downward")
DRIVER = Path(PACKAGE.submodule_search_locations[0]) / "downward" / "fast-downward.py"
SEARCH = "astar(lmcut())"


def solve(domain: str, problem: str) -> dict:
    """{"plan": [action names]} or {"error": why there is none}."""
    with tempfile.TemporaryDirectory() as work:
        plan_file = Path(work) / "plan"
        run = subprocess.run(
            [sys.executable, str(DRIVER), "--plan-file", str(plan_file), str(Path(domain).resolve()),
             str(Path(problem).resolve()), "--search", SEARCH],
            cwd=work, capture_output=True, text=True,
        )
        if run.returncode != 0 or not plan_file.exists():
            tail = (run.stdout + run.stderr).strip().splitlines()[-3:]
            return {"error": f"exit code {run.returncode}: " + " | ".join(tail)}
        lines = plan_file.read_text().splitlines()
    return {"plan": [line.strip("() ") for line in lines if line.startswith("(")]}


def solve_dir(folder: Path) -> tuple:
    return folder.name, solve(str(folder / "domain.pddl"), str(folder / "problem.pddl"))


def main(args: list) -> int:
    if len(args) == 2 and args[0] == "--batch":
        folders = sorted(p.parent for p in Path(args[1]).glob("*/domain.pddl"))
        with ProcessPoolExecutor(max_workers=2) as pool:
            print(json.dumps(dict(pool.map(solve_dir, folders, chunksize=8))))
        return 0
    if len(args) == 2:
        result = solve(args[0], args[1])
        if "error" in result:
            print(result["error"], file=sys.stderr)
            return 1
        print("\n".join(result["plan"]))
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
