#!/usr/bin/python3
"""Opens a RenderDoc capture of one fxlab frame with RenderDoc's Python replay module (Debian's
python3-renderdoc, for /usr/bin/python3) and checks what a student sees in qrenderdoc:

  check_capture.py CAPTURE.rdc REPORT.json FLOATS_DIR [--levels PREFIX,...] [--distinct-dispatches]
  check_capture.py CAPTURE.rdc --replay-only     only open it and replay it to its last event

- names: every texture a pass of the report's pass table reads or writes is, in the capture, a
  texture named as the table names it (a pooled texture's label lists every name it holds this
  frame, "bloom.down[0] | bloom.flicker"), used inside that pass's debug group; and no texture used
  inside a pass's group carries only names of other passes (a name that lies);
- 0 unnamed objects: every texture, buffer, sampler, framebuffer, program, shader, vertex array and
  query has a name that is not RenderDoc's own made-up one (the GL context itself has none to give);
- 0 work outside a debug group: every draw, dispatch, clear, copy and mipmap generation sits inside
  a group;
- with --distinct-dispatches: no two dispatches of one group (repeated work is told apart by its
  group's name);
- with --levels: every texture of the report whose name starts with a PREFIX has, at the end of the
  pass that writes it, the same floats in RenderDoc's replay as fxlab's own --capture-float wrote
  (FLOATS_DIR/<name>.pfm), every texel.
Exit 0 when all hold, 1 with every breach printed, 2 when the capture cannot be opened or replayed.
"""
import argparse
import json
import os
import struct
import sys

import renderdoc as rd

WORK = (rd.ActionFlags.Drawcall | rd.ActionFlags.Dispatch | rd.ActionFlags.Clear | rd.ActionFlags.Copy
        | rd.ActionFlags.GenMips | rd.ActionFlags.Resolve)
NAMED_TYPES = {rd.ResourceType.Texture, rd.ResourceType.Buffer, rd.ResourceType.Sampler, rd.ResourceType.Shader,
               rd.ResourceType.RenderPass, rd.ResourceType.StateObject, rd.ResourceType.Query,
               rd.ResourceType.View}
SEPARATOR = " | "  # render/texture_pool.hpp: TexturePool::kNameSeparator


def names_of(label):
    return label.split(SEPARATOR) if label else []


def file_stem(name):
    """app/capture.cpp's captureFileStem: the file a texture's floats go to."""
    stem = ""
    for ch in name:
        if ch.isascii() and (ch.isalnum() or ch in "._-"):
            stem += ch
        elif ch == "]":
            continue
        elif not stem or stem[-1] != "-":
            stem += "-"
    return stem or "texture"


def read_pfm(path):
    with open(path, "rb") as f:
        kind = f.readline().strip()
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        channels = 3 if kind == b"PF" else 1
        count = width * height * channels
        values = struct.unpack(("<" if scale < 0 else ">") + f"{count}f", f.read(4 * count))
    return width, height, channels, values


class Replay:
    def __init__(self, path):
        self.capture = rd.OpenCaptureFile()
        result = self.capture.OpenFile(path, "", None)
        if result.code != rd.ResultCode.Succeeded:
            raise RuntimeError(f"{path}: RenderDoc cannot open it: {result.Message()}")
        if self.capture.LocalReplaySupport() != rd.ReplaySupport.Supported:
            raise RuntimeError(f"{path}: RenderDoc cannot replay it on this machine "
                               f"({self.capture.DriverName()})")
        result, self.controller = self.capture.OpenCapture(rd.ReplayOptions(), None)
        if result.code != rd.ResultCode.Succeeded:
            raise RuntimeError(f"{path}: RenderDoc cannot replay it: {result.Message()}")
        self.sdfile = self.controller.GetStructuredFile()
        self.resources = {r.resourceId: r for r in self.controller.GetResources()}
        self.textures = {t.resourceId: t for t in self.controller.GetTextures()}
        # Every action with the names of the groups around it (outermost first).
        self.actions = []  # (action, name, [group names])
        self.group_events = {}  # outermost group name -> [first eventId, last eventId], each time it opens
        for root in self.controller.GetRootActions():
            self._walk(root, [])

    def _walk(self, action, groups):
        name = action.GetName(self.sdfile)
        if action.flags & rd.ActionFlags.PushMarker:
            inner = groups + [name]
            first = action.eventId
            for child in action.children:
                self._walk(child, inner)
            last = max([first] + [e.eventId for c in action.children for e in c.events] +
                       [c.eventId for c in action.children])
            self.group_events.setdefault(tuple(inner), []).append((first, last))
            return
        self.actions.append((action, name, groups))
        for child in action.children:
            self._walk(child, groups)

    def name(self, resource_id):
        r = self.resources.get(resource_id)
        return "" if r is None or r.autogeneratedName else r.name

    def shutdown(self):
        self.controller.Shutdown()
        self.capture.Shutdown()


def pass_spans(replay, passes):
    """pass name -> [(first, last) event ids] of its outermost group (the executor's one per pass)."""
    spans = {}
    for groups, ranges in replay.group_events.items():
        if len(groups) >= 1 and groups[-1] in passes:
            spans.setdefault(groups[-1], []).extend(ranges)
    return spans


def check_names(replay, report):
    failures = []
    executed = {p["name"]: p for p in report["passes"] if p.get("executed")}
    logical = {t["name"] for t in report["textures"] if t.get("allocated", True)}
    spans = pass_spans(replay, executed)
    usage = {tid: replay.controller.GetUsage(tid) for tid in replay.textures}

    def used_in(span_list):
        found = set()
        for tid, uses in usage.items():
            if any(first <= u.eventId <= last for u in uses for first, last in span_list):
                found.add(tid)
        return found

    # The report is the run's last frame, which keeps every texture for the captures and so also runs
    # the passes only a capture reads (a view nothing else in the frame reads); a frame before it skips
    # those, so their absence from the capture is no breach. Any other pass must be there.
    read_by_others = {n for p in executed.values() for n in p.get("reads", [])}
    checked = 0
    for name, p in executed.items():
        if name not in spans:
            if any(w in read_by_others or w == "output" for w in p.get("writes", [])):
                failures.append(f"pass '{name}': no debug group of that name in the capture")
            continue
        used = used_in(spans[name])
        wanted = [n for n in p.get("reads", []) + p.get("writes", []) if n in logical]
        for n in wanted:
            checked += 1
            if not any(n in names_of(replay.name(t)) for t in used):
                seen = sorted(replay.name(t) or str(t) for t in used)
                failures.append(f"pass '{name}': uses '{n}', but no texture of that name is used in its group "
                                f"(used: {', '.join(seen) or 'none'})")
        for t in used:
            held = names_of(replay.name(t))
            frame_names = [h for h in held if h in logical]
            if frame_names and not set(frame_names) & set(wanted):
                failures.append(f"pass '{name}': uses a texture named '{replay.name(t)}', none of them a name "
                                f"the pass table gives it (it reads/writes {', '.join(wanted) or 'nothing named'})")
    return failures, checked


def check_unnamed(replay):
    unnamed = [r for r in replay.resources.values() if r.type in NAMED_TYPES and r.autogeneratedName]
    return [f"unnamed {str(r.type).split('.')[-1]}: RenderDoc calls it '{r.name}'" for r in unnamed]


def check_grouped(replay, distinct_dispatches):
    failures = []
    work = 0
    dispatches = {}
    for action, name, groups in replay.actions:
        if not action.flags & WORK:
            continue
        work += 1
        if not groups:
            failures.append(f"event {action.eventId}: {name} outside every debug group")
        if action.flags & rd.ActionFlags.Dispatch:
            dispatches.setdefault(tuple(groups), []).append(action.eventId)
    if distinct_dispatches:
        for groups, events in dispatches.items():
            if len(events) > 1:
                failures.append(f"{len(events)} dispatches in one group '{' / '.join(groups)}' (events "
                                f"{', '.join(map(str, events))}): nothing tells them apart")
    return failures, work


def texel_floats(data, fmt, count):
    """The first three channels (or one) of every texel of RenderDoc's bytes, as Python floats."""
    width = fmt.compByteWidth
    comps = fmt.compCount
    code = {2: "e", 4: "f"}.get(width)
    if code is None or fmt.compType != rd.CompType.Float:
        return None
    values = struct.unpack(f"<{count * comps}{code}", data[: count * comps * width])
    keep = 3 if comps >= 3 else 1
    out = []
    for i in range(count):
        out.extend(values[i * comps: i * comps + keep])
    return out, keep


def check_levels(replay, report, floats_dir, prefixes):
    failures = []
    compared = 0
    producers = {t["name"]: t.get("producer") for t in report["textures"]}
    spans = pass_spans(replay, {p["name"] for p in report["passes"] if p.get("executed")})
    for name in sorted(producers):
        if not any(name.startswith(p) for p in prefixes):
            continue
        producer = producers[name]
        pfm = os.path.join(floats_dir, file_stem(name) + ".pfm")
        if not producer or producer not in spans or not os.path.exists(pfm):
            failures.append(f"'{name}': no producing pass in the capture or no {pfm}")
            continue
        texture = next((t for tid, t in replay.textures.items() if name in names_of(replay.name(tid))), None)
        if texture is None:
            failures.append(f"'{name}': no texture of that name in the capture")
            continue
        width, height, channels, expected = read_pfm(pfm)
        last = max(last for first, last in spans[producer])
        replay.controller.SetFrameEvent(last, True)
        data = bytes(replay.controller.GetTextureData(texture.resourceId, rd.Subresource(0, 0, 0)))
        got = texel_floats(data, texture.format, texture.width * texture.height)
        if got is None:
            failures.append(f"'{name}': not a float texture in the capture ({texture.format.Name()})")
            continue
        values, keep = got
        if (texture.width, texture.height) != (width, height) or keep != channels:
            failures.append(f"'{name}': {texture.width}x{texture.height}x{keep} in the capture, "
                            f"{width}x{height}x{channels} in {pfm}")
            continue
        # The PFM's rows go bottom-up, as GL's; RenderDoc's bytes too (GL's texel order).
        differ = sum(1 for i in range(width * height)
                     if any(values[i * keep + c] != expected[i * keep + c] for c in range(keep)))
        compared += 1
        if differ:
            failures.append(f"'{name}': {differ} of {width * height} texels differ from {pfm}")
    return failures, compared


def main(argv):
    parser = argparse.ArgumentParser(description="checks a RenderDoc capture of one fxlab frame")
    parser.add_argument("capture")
    parser.add_argument("report", nargs="?")
    parser.add_argument("floats_dir", nargs="?")
    parser.add_argument("--replay-only", action="store_true",
                        help="only open the capture and replay it to its last event")
    parser.add_argument("--levels", default="")
    parser.add_argument("--distinct-dispatches", action="store_true")
    a = parser.parse_args(argv[1:])
    capture, report_path, floats_dir = a.capture, a.report, a.floats_dir
    prefixes = [p for p in a.levels.split(",") if p]
    if not a.replay_only and not (report_path and floats_dir):
        parser.error("REPORT and FLOATS_DIR are needed unless --replay-only")
    rd.InitialiseReplay(rd.GlobalEnvironment(), [])
    try:
        replay = Replay(capture)
    except RuntimeError as e:
        print(f"FAIL: {e}")
        rd.ShutdownReplay()
        return 2
    if a.replay_only:
        last = max((action.eventId for action, _, _ in replay.actions), default=0)
        replay.controller.SetFrameEvent(last, True)
        print(f"{capture}: opened and replayed to event {last}: {len(replay.actions)} actions, "
              f"{len(replay.resources)} objects")
        replay.shutdown()
        rd.ShutdownReplay()
        return 0 if replay.actions else 1
    with open(report_path) as f:
        report = json.load(f)
    failures = []
    names, checked = check_names(replay, report)
    unnamed = check_unnamed(replay)
    grouped, work = check_grouped(replay, a.distinct_dispatches)
    levels, compared = check_levels(replay, report, floats_dir, prefixes) if prefixes else ([], 0)
    failures = names + unnamed + grouped + levels
    print(f"{capture}: {len(replay.resources)} objects ({len(unnamed)} unnamed), {len(replay.textures)} textures, "
          f"{checked} pass-table names found in their passes, {work} actions of GPU work "
          f"({sum(1 for f in grouped if 'outside' in f)} outside a group), {compared} textures' floats compared")
    for f in failures:
        print(f"FAIL: {f}")
    replay.shutdown()
    rd.ShutdownReplay()
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
