#!/usr/bin/env python3
"""Checks fxlab's rule that every GL object has a label and every piece of GPU work runs inside a
debug group, so RenderDoc and apitrace show names, on the text of `apitrace dump TRACE`.

  check_gl_names.py DUMP.txt [--expect-work]

Objects: every name made by glCreate*/glGen* (textures, buffers, framebuffers, vertex arrays,
samplers, renderbuffers, queries, program pipelines, transform feedbacks) and by glCreateProgram
and glCreateShader must get a glObjectLabel before it is deleted or the trace ends.
Work: every draw, dispatch, clear, blit, image copy and mipmap generation must be issued inside
at least one glPushDebugGroup, from the moment the program turns GL_DEBUG_OUTPUT on (the window
library may clear a new window before that).
One exception, said where it is made (common/ui/overlay.cpp): Dear ImGui's GL backend, Debian's
and unchanged, makes its objects without labels; objects made inside a debug group whose name
contains "Dear ImGui" need none.
Exit status 0 when the trace keeps the rule, 1 when it does not (each breach is printed with its
call number), 2 when the dump cannot be read or holds no GL work at all with --expect-work.
"""
import re
import sys

CALL = re.compile(r'^(\d+) (gl\w+)\((.*)\)(?: = (.*))?$')
# glCreate<X> / glGen<X> -> the label identifier, and the argument that holds the new names.
MADE = {
    'Textures': ('GL_TEXTURE', 'textures'),
    'Buffers': ('GL_BUFFER', 'buffers'),
    'Framebuffers': ('GL_FRAMEBUFFER', 'framebuffers'),
    'VertexArrays': ('GL_VERTEX_ARRAY', 'arrays'),
    'Samplers': ('GL_SAMPLER', 'samplers'),
    'Renderbuffers': ('GL_RENDERBUFFER', 'renderbuffers'),
    'Queries': ('GL_QUERY', 'ids'),
    'ProgramPipelines': ('GL_PROGRAM_PIPELINE', 'pipelines'),
    'TransformFeedbacks': ('GL_TRANSFORM_FEEDBACK', 'ids'),
}
WORK = re.compile(r'^gl(Draw\w*|MultiDraw\w*|DispatchCompute\w*|Clear|ClearBuffer\w*|'
                  r'ClearNamedFramebuffer\w*|ClearNamedBuffer\w*|ClearTex\w*|Blit\w*|CopyImageSubData|'
                  r'CopyTex\w*|CopyTexture\w*|CopyNamedBufferSubData|CopyBufferSubData|Generate\w*Mipmap)$')
THIRD_PARTY_GROUP = 'Dear ImGui'


def names_in(args, key):
    m = re.search(r'\b' + key + r' = (&\d+|\{[\d, ]*\})', args)
    return [int(v) for v in re.findall(r'\d+', m.group(1))] if m else []


def check(lines):
    alive = {}  # (identifier, name) -> [call, maker, labelled, exempt]
    groups = []  # names of the open debug groups
    breaches = []
    counts = {'objects': 0, 'labelled': 0, 'exempt': 0, 'work': 0}
    watching = False  # from glEnable(GL_DEBUG_OUTPUT) on
    calls = 0
    for line in lines:
        m = CALL.match(line.rstrip('\n'))
        if not m:
            continue
        calls += 1
        no, fn, args, result = int(m.group(1)), m.group(2), m.group(3), m.group(4)
        in_third_party = any(THIRD_PARTY_GROUP in g for g in groups)

        made = re.match(r'gl(?:Create|Gen)(\w+)$', fn)
        if made and made.group(1) in MADE:
            identifier, key = MADE[made.group(1)]
            for n in names_in(args, key):
                alive[(identifier, n)] = [no, fn, False, in_third_party]
            continue
        if fn in ('glCreateProgram', 'glCreateShader') and result and result.isdigit():
            identifier = 'GL_PROGRAM' if fn == 'glCreateProgram' else 'GL_SHADER'
            alive[(identifier, int(result))] = [no, fn, False, in_third_party]
            continue
        if fn == 'glObjectLabel':
            k = re.search(r'identifier = (\w+), name = (\d+)', args)
            if k and (k.group(1), int(k.group(2))) in alive:
                alive[(k.group(1), int(k.group(2)))][2] = True
            continue
        deleted = re.match(r'glDelete(\w+)$', fn)
        if deleted:
            kind = deleted.group(1)
            if kind in ('Program', 'Shader'):
                identifier = 'GL_' + kind.upper()
                v = re.search(r'= (\d+)', args)
                gone = [int(v.group(1))] if v else []
            elif kind in MADE:
                identifier = MADE[kind][0]
                gone = names_in(args, MADE[kind][1])
            else:
                continue
            for n in gone:
                obj = alive.pop((identifier, n), None)
                if obj:
                    breaches += settle(identifier, n, obj, counts, f'deleted at call {no}')
            continue
        if fn == 'glEnable' and 'GL_DEBUG_OUTPUT' in args and 'SYNCHRONOUS' not in args:
            watching = True
            continue
        if fn == 'glPushDebugGroup':
            g = re.search(r'message = "([^"]*)"', args)
            groups.append(g.group(1) if g else '')
            continue
        if fn == 'glPopDebugGroup':
            if groups:
                groups.pop()
            continue
        if WORK.match(fn) and watching:
            counts['work'] += 1
            if not groups:
                breaches.append(f'call {no}: {fn} is outside any debug group')
    for (identifier, n), obj in alive.items():
        breaches += settle(identifier, n, obj, counts, 'alive when the trace ends')
    return calls, counts, breaches


def settle(identifier, name, obj, counts, when):
    counts['objects'] += 1
    made_at, maker, labelled, exempt = obj
    if labelled:
        counts['labelled'] += 1
        return []
    if exempt:
        counts['exempt'] += 1
        return []
    return [f'call {made_at}: {identifier} {name} made by {maker} has no label ({when})']


def main(argv):
    if len(argv) < 2 or len(argv) > 3 or (len(argv) == 3 and argv[2] != '--expect-work'):
        print(__doc__.strip().split('\n\n')[1], file=sys.stderr)
        return 2
    try:
        with open(argv[1], errors='replace') as f:
            calls, counts, breaches = check(f)
    except OSError as e:
        print(f'{argv[1]}: cannot read the dump: {e.strerror}', file=sys.stderr)
        return 2
    if len(argv) == 3 and counts['work'] == 0:
        print(f'{argv[1]}: no GL work in the trace ({calls} calls): nothing was checked', file=sys.stderr)
        return 2
    for b in breaches:
        print(f'{argv[1]}: {b}')
    print(f'{argv[1]}: {counts["objects"]} objects ({counts["labelled"]} labelled, {counts["exempt"]} '
          f"Dear ImGui's), {counts['work']} calls that do GPU work: {len(breaches)} breach(es)")
    return 1 if breaches else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
