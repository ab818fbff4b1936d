#!/usr/bin/python3
"""SciPy's DOP853 on epviz's heavy-top problem, a peer `epviz bench` compares with.

Run with /usr/bin/python3 (Debian's python3-scipy). Reads one JSON object on
stdin:
  {"inertia": [I1, I2, I3], "com": [a0, b0, c0], "weight": P,
   "omega0": [...], "gamma0": [...], "t_end": T, "tolerances": [...], "repeats": n}
and writes one JSON object on stdout:
  {"scipy": "<version>", "results": [{"method": "dop853-solve_ivp" | "dop853-ode",
    "tol": tol, "status": "ok" | "failed", "reason": "...", "t": t,
    "omega": [...], "gamma": [...], "nfev": n, "steps": n (-1 if unknown),
    "cpu_seconds": median, "repeats": n}, ...]}
or {"skipped": "<reason>"} when scipy cannot be imported.
rtol = atol = tol; CPU time is time.process_time() around the solver call only.

The right-hand side is the Euler-Poisson system in its direct form
(math.md eqs. 1.1-1.2), the equations of epviz's physics::DirectSystem:
  I Omega' = (I Omega) x Omega + gamma x (P r),   gamma' = gamma x Omega.
"""
import json
import statistics
import sys
import time


def make_rhs(inertia, com, weight, counter):
    i1, i2, i3 = (float(v) for v in inertia)
    j1, j2, j3 = 1.0 / i1, 1.0 / i2, 1.0 / i3
    p1, p2, p3 = (weight * float(v) for v in com)

    def rhs(t, x):
        counter[0] += 1
        w1, w2, w3, g1, g2, g3 = x[0], x[1], x[2], x[3], x[4], x[5]
        return [
            ((i2 - i3) * w2 * w3 + g2 * p3 - g3 * p2) * j1,
            ((i3 - i1) * w3 * w1 + g3 * p1 - g1 * p3) * j2,
            ((i1 - i2) * w1 * w2 + g1 * p2 - g2 * p1) * j3,
            w3 * g2 - w2 * g3,
            w1 * g3 - w3 * g1,
            w2 * g1 - w1 * g2,
        ]

    return rhs


def solve_ivp_once(problem, tol):
    from scipy.integrate import solve_ivp
    counter = [0]
    rhs = make_rhs(problem["inertia"], problem["com"], problem["weight"], counter)
    y0 = list(problem["omega0"]) + list(problem["gamma0"])
    t_end = float(problem["t_end"])
    start = time.process_time()
    sol = solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", rtol=tol, atol=tol,
                    t_eval=None, dense_output=False)
    cpu = time.process_time() - start
    y = sol.y[:, -1]
    return {
        "ok": bool(sol.success), "reason": "" if sol.success else str(sol.message),
        "t": float(sol.t[-1]), "y": [float(v) for v in y], "nfev": int(sol.nfev),
        "steps": int(len(sol.t) - 1), "cpu": cpu,
    }


def ode_once(problem, tol):
    from scipy.integrate import ode
    counter = [0]
    rhs = make_rhs(problem["inertia"], problem["com"], problem["weight"], counter)
    y0 = list(problem["omega0"]) + list(problem["gamma0"])
    t_end = float(problem["t_end"])
    start = time.process_time()
    r = ode(rhs).set_integrator("dop853", rtol=tol, atol=tol, nsteps=10**8)
    r.set_initial_value(y0, 0.0)
    r.integrate(t_end)
    cpu = time.process_time() - start
    ok = r.successful()
    return {
        "ok": bool(ok), "reason": "" if ok else "dop853 return code %s" % r.get_return_code(),
        "t": float(r.t), "y": [float(v) for v in r.y], "nfev": counter[0],
        "steps": -1, "cpu": cpu,
    }


def timed(fn, problem, tol, repeats):
    first = fn(problem, tol)
    cpus = [first["cpu"]]
    n = min(repeats, 2) if first["cpu"] > 0.5 else repeats
    if first["ok"]:
        for _ in range(1, n):
            cpus.append(fn(problem, tol)["cpu"])
    return {
        "tol": tol, "status": "ok" if first["ok"] else "failed", "reason": first["reason"],
        "t": first["t"], "omega": first["y"][:3], "gamma": first["y"][3:],
        "nfev": first["nfev"], "steps": first["steps"],
        "cpu_seconds": statistics.median(cpus), "repeats": len(cpus),
    }


def main():
    problem = json.load(sys.stdin)
    try:
        import scipy
        import scipy.integrate  # noqa: F401
    except Exception as e:  # ImportError, or a broken install
        json.dump({"skipped": "scipy not importable by %s: %s" % (sys.executable, e)}, sys.stdout)
        return 0
    repeats = max(1, int(problem.get("repeats", 1)))
    results = []
    for method, fn in (("dop853-solve_ivp", solve_ivp_once), ("dop853-ode", ode_once)):
        for tol in problem["tolerances"]:
            try:
                row = timed(fn, problem, float(tol), repeats)
            except Exception as e:
                row = {"tol": tol, "status": "failed", "reason": "%s: %s" % (type(e).__name__, e)}
            row["method"] = method
            results.append(row)
    json.dump({"scipy": scipy.__version__, "results": results}, sys.stdout)
    return 0


if __name__ == "__main__":
    sys.exit(main())
