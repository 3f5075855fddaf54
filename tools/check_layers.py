#!/usr/bin/env python3
"""Holds the tree to cmake/layers.txt: no include and no link runs up a layer or across to a sibling.

Usage: check_layers.py SOURCE_DIR LINKS_FILE
LINKS_FILE is written by CMake at configure time (cmake/WtcLibrary.cmake): one line per target,
'<target>: <direct link dependency>;...'. Prints every violation with its file and line; exits 1 if any.
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
PRIVATE_ROOTS = ['src']
ENGINE = '{engine}'


def public_roots(root):
    """include/, and each plugins/<folder>/include/ (the engines' adapters, the engine table)."""
    plugins = os.path.join(root, 'plugins')
    folders = sorted(os.listdir(plugins)) if os.path.isdir(plugins) else []
    return ['include'] + [f'plugins/{f}/include' for f in folders if os.path.isdir(os.path.join(plugins, f, 'include'))]


def read_layers(root, path):
    units, only, templates = [], {}, []
    for n, line in enumerate(open(path), 1):
        line = line.split('#', 1)[0].split()
        if not line:
            continue
        if line[0] == 'only':
            only[line[1]] = set(line[2].split(','))
            continue
        level, name, targets, folders = int(line[0]), line[1], line[2].split(','), line[3:]
        unit = {'level': level, 'name': name, 'targets': targets, 'folders': folders}
        (templates if name == ENGINE else units).append(unit)
    # {engine}: one unit per folder of its folders' parent that no other unit names.
    named = {f for u in units for f in u['folders']}
    for t in templates:
        parent = os.path.dirname(t['folders'][0])
        for entry in sorted(os.listdir(os.path.join(root, parent))):
            folder = f'{parent}/{entry}'
            if folder in named or not os.path.isdir(os.path.join(root, folder)):
                continue
            units.append({'level': t['level'], 'name': entry,
                          'targets': [x.replace(ENGINE, entry) for x in t['targets']],
                          'folders': [x.replace(ENGINE, entry) for x in t['folders']]})
    return units, only


def unit_of(path, units):
    best = None
    for u in units:
        for f in u['folders']:
            if path == f or path.startswith(f + '/'):
                if best is None or len(f) > best[1]:
                    best = (u, len(f))
    return best[0] if best else None


def sees(a, b):
    """Whether unit a may use unit b."""
    return a is b or b['level'] < a['level']


def resolve(root, including, name, units, roots):
    """The file an include names: beside the including file, under a public or private root, or under the
    including file's own unit's folders (an engine's folder is its libraries' private root)."""
    here = unit_of(including, units)
    own = [f for f in here['folders'] if f.startswith('plugins/')] if here is not None else []
    for base in [os.path.dirname(including)] + roots + PRIVATE_ROOTS + own:
        candidate = os.path.normpath(os.path.join(base, name))
        if os.path.isfile(os.path.join(root, candidate)):
            return candidate
    return None


def check_includes(root, units):
    problems = []
    roots = public_roots(root)
    for u in units:
        for folder in u['folders']:
            for dirpath, _, files in os.walk(os.path.join(root, folder)):
                for f in files:
                    if not f.endswith(('.hpp', '.cpp', '.h')):
                        continue
                    path = os.path.relpath(os.path.join(dirpath, f), root)
                    here = unit_of(path, units)
                    for n, line in enumerate(open(os.path.join(root, path)), 1):
                        m = INCLUDE.match(line)
                        if not m:
                            continue
                        target = resolve(root, path, m.group(1), units, roots)
                        if target is None:
                            continue
                        there = unit_of(target, units)
                        if there is not None and not sees(here, there):
                            problems.append(f'{path}:{n}: includes {target}: layer {here["name"]} '
                                            f'(level {here["level"]}) may not see {there["name"]} '
                                            f'(level {there["level"]})')
    return problems


def check_links(links_file, units, only):
    level, unit = {}, {}
    for u in units:
        for t in u['targets']:
            if t not in unit or u['level'] > unit[t]['level']:
                unit[t] = u
    deps = {}
    for line in open(links_file):
        if ':' not in line:
            continue
        target, rest = line.split(':', 1)
        deps[target.strip()] = [d for d in rest.strip().split(';') if d]
    problems = []
    for t, ds in deps.items():
        for d in ds:
            if t in unit and d in unit and not sees(unit[t], unit[d]):
                problems.append(f'target {t} (layer {unit[t]["name"]}) links {d} (layer {unit[d]["name"]}): '
                                f'a link may not run up a layer or across to a sibling')
    for t, allowed in only.items():
        if t not in deps:
            problems.append(f'target {t} (named in cmake/layers.txt) is not in the build')
            continue
        seen, todo = set(), list(deps[t])
        while todo:
            d = todo.pop()
            if d in seen or d not in deps and d not in unit:
                continue
            seen.add(d)
            todo.extend(deps.get(d, []))
        ours = {d for d in seen if d in unit}
        if ours != allowed:
            problems.append(f'target {t} links {sorted(ours)} of WTC\'s libraries; cmake/layers.txt allows '
                            f'exactly {sorted(allowed)}')
    return problems


def main():
    root, links = sys.argv[1], sys.argv[2]
    units, only = read_layers(root, os.path.join(root, 'cmake/layers.txt'))
    problems = check_includes(root, units) + check_links(links, units, only)
    for p in problems:
        print(p)
    print(f'check_layers: {len(problems)} violation(s) of cmake/layers.txt')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
