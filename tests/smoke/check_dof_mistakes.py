#!/usr/bin/env python3
"""Lesson 09's mistakes shown on purpose, read back from the report (texture statistics and facts):
  step 1, shown_target: a glTexImage2D target with MIN_FILTER at its mipmapped default samples black
  although the scene's colour was copied into it; depth read with COMPARE_MODE on reads 0 or 1
  everywhere, while the plain read gives the depth texture's values;
  step 1, incomplete_fbo: glCheckNamedFramebufferStatus does not say complete, fxlab's message names
  the status and the framebuffer, no GL error, and the lesson still draws;
  step 4, coc_near: the CoC pass told another near plane moves the focus to where the facts say.
usage: check_dof_mistakes.py <lesson 09 exe> <work dir>"""
import math
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from report import load  # noqa: E402 (tests/smoke/report.py: the smoke checks' one report reader)

exe, work = sys.argv[1], sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []


def run(name, step, *params):
    report = os.path.join(work, name + ".json")
    args = [exe, "--headless", "--size", "64x36", "--frames", "2", "--step", str(step), "--report", report]
    for p in params:
        args += ["--param", p]
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"FAIL: {name} exited with {done.returncode}:\n{done.stdout}{done.stderr}")
    r = load(report)
    if r["glErrors"]:
        failures.append(f"{name}: {r['glErrors']} GL errors")
    return r


def stats(report, texture):
    for t in report["textures"]:
        if t["name"] == texture and t.get("stats"):
            return t["stats"]
    return None


def check(ok, message):
    if not ok:
        failures.append(message)


# Off by default: no extra pass, nothing named fbo.shown.
plain = run("colour", 1)
check(stats(plain, "fbo.shown") is None, "shown_target=colour made fbo.shown")

mip = run("mipmap", 1, "shown_target=colour-mipmap-min-filter")
raw, shown = stats(mip, "fbo.raw_target"), stats(mip, "fbo.shown")
check(raw is not None and max(raw[c]["max"] for c in range(3)) > 0.1, f"the raw target holds no picture: {raw}")
check(shown is not None and all(shown[c]["max"] == 0.0 for c in range(3)),
      f"the incomplete raw target did not sample black: {shown}")

depth = stats(run("depth", 1, "shown_target=depth"), "fbo.shown")
scene_depth = stats(plain, "scene.depth")[0]
check(depth is not None and abs(depth[0]["min"] - scene_depth["min"]) < 1e-3
      and abs(depth[0]["mean"] - scene_depth["mean"]) < 1e-3 and scene_depth["max"] > scene_depth["min"],
      f"the plain depth read is not the depth texture: {depth} against {scene_depth}")
compared = stats(run("compare", 1, "shown_target=depth-compare-mode"), "fbo.shown")
check(compared is not None and all(compared[c]["min"] == compared[c]["max"] in (0.0, 1.0) for c in range(3)),
      f"depth with COMPARE_MODE on did not read one value of 0 or 1: {compared}")

for kind in ("rgb9e5-colour", "no-attachment"):
    r = run("incomplete-" + kind, 1, "incomplete_fbo=" + kind)
    status, message = r["facts"].get("incompleteFboStatus", ""), r["facts"].get("incompleteFboMessage", "")
    check(status.startswith("GL_FRAMEBUFFER_") and status != "GL_FRAMEBUFFER_COMPLETE",
          f"{kind}: status {status!r}")
    check(message == f"{status} on fbo.incomplete", f"{kind}: message {message!r}")
    colour = stats(r, "scene.color")
    check(colour == stats(plain, "scene.color"), f"{kind}: the lesson's picture changed")
check("incompleteFboStatus" not in plain["facts"], "incomplete_fbo=none reports a status")

# coc_near: the scene's projection has near 0.5 m, far 500 m; the CoC pass is told 0.6 m.
def window_depth(d, n, f):
    return (1 / n - 1 / d) / (1 / n - 1 / f)


def linear(z, n, f):
    return 1 / (1 / n - z * (1 / n - 1 / f))


agree = run("coc-agree", 4)
moved = run("coc-near", 4, "coc_near=0.6")
focus = float(moved["facts"]["focus"])
expected = linear(window_depth(focus, 0.6, 500), 0.5, 500)
lands = float(moved["facts"].get("focusLandsAt", "nan"))
check(math.isclose(lands, expected, rel_tol=1e-4), f"focusLandsAt {lands}, expected {expected}")
check(lands < focus - 1, f"the focus did not move nearer: {lands} m for {focus} m")
check("focusLandsAt" not in agree["facts"], "coc_near=0 reports a moved focus")
a, b = stats(agree, "dof.coc"), stats(moved, "dof.coc")
check(a is not None and b is not None and abs(a[0]["min"] - b[0]["min"]) > 0.1,
      f"the CoC did not change with coc_near: {a} against {b}")

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
