"""Writes cpp/python/contracts.hpp: the comments of the C++ headers (cpp/include/hinf), by name, for
the Python docstrings.

The contract of a function, a class or a field (what it computes, the paper's equations, units,
what it throws, thread safety) is written once, as the comment of its declaration in the C++
header. The bindings compose each Python docstring from that comment and the sections only
Python has (parameters as NumPy arrays, an example), so the contract reaches ``help()`` without
being written twice. Keys:

  ``control/riccati.hpp``            the comment at the top of a header (before ``#pragma once``)
  ``solve_grde``, ``Trajectory``      the comment block right above a declaration at namespace scope
  ``Trajectory::A_e``                 ... above a member (overloads: their comments in order)
  ``SolverOptions::rtol``             a field's trailing comment and its continuation lines
  ``Method::bdf``                     an enumerator's trailing comment (its name lower-cased)

    python scripts/generate_contracts.py            # writes the file
    python scripts/generate_contracts.py --check    # exit status 1 when the file is not up to date

(tests/python/test_stubs.py runs the check.)
"""

from __future__ import annotations

import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
HEADERS = ROOT / "cpp" / "include" / "hinf"
OUTPUT = ROOT / "cpp" / "python" / "contracts.hpp"

SCOPE = re.compile(r"^\s*(?:template\s*<[^>]*>\s*)?(?:class|struct)\s+(\w+)\b[^;]*$")
ENUM = re.compile(r"^\s*enum class\s+(\w+)")
NAMESPACE = re.compile(r"^\s*namespace\s*[\w:]*\s*\{")
FUNCTION = re.compile(r"^\s*(?:\[\[[^\]]*\]\]\s*)?(?:(?:virtual|static|explicit|inline|constexpr|friend)\s+)*"
                      r"(?:[\w:<>,*&\s]+?[\s*&])?(~?\w+)\s*\(")
FIELD = re.compile(r"^\s*[\w:<>,\s*&]+?\b(\w+)\s*(?:=[^;]*|\{[^;]*\})?;\s*//\s?(.*)$")
ENUMERATOR = re.compile(r"^\s*(\w+)\s*(?:=\s*[^,/]*)?,?\s*//\s?(.*)$")
KEYWORDS = {"if", "for", "while", "return", "switch", "sizeof", "require", "static_assert", "operator"}


def comment_text(line: str) -> str | None:
    stripped = line.strip()
    return stripped[2:].removeprefix(" ") if stripped.startswith("//") else None


def extract(path: pathlib.Path) -> dict[str, list[str]]:
    """Key -> comment paragraphs of one header."""
    lines = path.read_text().splitlines()
    found: dict[str, list[str]] = {}

    def add(key: str, text: list[str]) -> None:
        body = "\n".join(text).strip()
        if body and body not in found.setdefault(key, []):
            found[key].append(body)

    # The file's comment: the lines before #pragma once.
    top = []
    for line in lines:
        if line.startswith("#pragma once"):
            break
        text = comment_text(line)
        if text is not None:
            top.append(text)
    add(path.relative_to(HEADERS).as_posix(), top)

    scopes: list[tuple[str, int]] = []  # (class or enum name, "" for a namespace; brace depth inside it)
    depth = 0
    block: list[str] = []
    pending_scope: str | None = None
    last_field: tuple[str, int] | None = None  # key and column of a trailing comment that may continue
    for line in lines:
        text = comment_text(line)
        if text is not None:
            if last_field and line.index("//") == last_field[1]:
                found[last_field[0]][-1] += "\n" + text  # continues a field's trailing comment
                continue
            block.append(text)
            continue
        last_field = None
        code = line.split("//")[0]
        scope_names = [name for name, _ in scopes if name]
        inside_code = depth > (scopes[-1][1] if scopes else 0)  # in a function body or an initializer
        prefix = "::".join(scope_names)
        qualify = (lambda name: f"{prefix}::{name}" if prefix else name)
        if not inside_code and code.strip():
            if NAMESPACE.match(code):
                pending_scope = ""
            elif match := ENUM.match(code):
                add(qualify(match.group(1)), block)
                pending_scope = match.group(1)
            elif (match := SCOPE.match(code)) and not code.rstrip().endswith(";"):
                add(qualify(match.group(1)), block)
                pending_scope = match.group(1)
            elif scope_names and scope_names[-1].startswith("enum ") and (match := ENUMERATOR.match(line)):
                key = f"{'::'.join(n.removeprefix('enum ') for n in scope_names)}::{match.group(1).lower()}"
                add(key, [match.group(2)])
                last_field = (key, line.index("//"))
            elif (match := FUNCTION.match(code)) and match.group(1) not in KEYWORDS:
                add(qualify(match.group(1)), block)
            elif scope_names and (match := FIELD.match(line)):
                key = qualify(match.group(1))
                add(key, block + [match.group(2)])
                last_field = (key, line.index("//"))
        block = []
        for char in code:
            if char == "{":
                depth += 1
                if pending_scope is not None:
                    is_enum = ENUM.match(code) is not None
                    scopes.append((("enum " if is_enum else "") + pending_scope, depth))
                    pending_scope = None
            elif char == "}":
                if scopes and scopes[-1][1] == depth:
                    scopes.pop()
                depth -= 1
    return found


def contracts() -> dict[str, str]:
    table: dict[str, list[str]] = {}
    for path in sorted(HEADERS.glob("*/*.hpp")):
        for key, texts in extract(path).items():
            for text in texts:
                if text not in table.setdefault(key, []):
                    table[key].append(text)
    return {key: "\n\n".join(texts) for key, texts in sorted(table.items()) if texts}


def render(table: dict[str, str]) -> str:
    entries = "".join(f"    {{{cpp_string(key)}, R\"contract({text})contract\"}},\n" for key, text in table.items())
    return f"""// Generated by scripts/generate_contracts.py from the comments of cpp/include/hinf: do not edit.
// The contract of each C++ declaration by name, for the Python docstrings (casters.hpp, contract()).
#pragma once

#include <string_view>
#include <utility>

namespace hinf::python {{

inline constexpr std::pair<std::string_view, std::string_view> kContracts[] = {{
{entries}}};

}}  // namespace hinf::python
"""


def cpp_string(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def main() -> int:
    text = render(contracts())
    if "--check" in sys.argv[1:]:
        if not OUTPUT.exists() or OUTPUT.read_text() != text:
            print(f"{OUTPUT.relative_to(ROOT)} is not up to date: run python scripts/generate_contracts.py",
                  file=sys.stderr)
            return 1
        return 0
    OUTPUT.write_text(text)
    print(OUTPUT.relative_to(ROOT))
    return 0


if __name__ == "__main__":
    sys.exit(main())
