"""A small C++ reader for the exercise marks: enough to find the function around a mark, its parameters,
the locals declared before the mark, and a file's internal-linkage helpers. Comments, strings and
preprocessor lines are skipped; it is not a parser, and the student edition's build checks what it did."""

from __future__ import annotations

import re
from dataclasses import dataclass

KEYWORDS = {
    "alignas", "alignof", "and", "asm", "auto", "bool", "break", "case", "catch", "char", "char8_t", "char16_t",
    "char32_t", "class", "co_await", "co_return", "co_yield", "concept", "const", "consteval", "constexpr",
    "constinit", "const_cast", "continue", "decltype", "default", "delete", "do", "double", "dynamic_cast",
    "else", "enum", "explicit", "export", "extern", "false", "float", "for", "friend", "goto", "if", "inline",
    "int", "long", "mutable", "namespace", "new", "noexcept", "not", "nullptr", "operator", "or", "private",
    "protected", "public", "register", "reinterpret_cast", "requires", "return", "short", "signed", "sizeof",
    "static", "static_assert", "static_cast", "struct", "switch", "template", "this", "thread_local", "throw",
    "true", "try", "typedef", "typeid", "typename", "union", "unsigned", "using", "virtual", "void",
    "volatile", "wchar_t", "while",
}
STATEMENT_KEYWORDS = {
    "return", "if", "for", "while", "do", "switch", "throw", "case", "default", "goto", "break", "continue",
    "using", "typedef", "static_assert", "co_return", "else", "try", "delete", "namespace", "struct", "class",
    "enum", "union", "template", "friend", "asm",
}
TOKEN_RE = re.compile(
    r"""(?P<ws>[ \t\r\f\v]+)
      | (?P<nl>\n)
      | (?P<comment>//[^\n]*|/\*.*?\*/)
      | (?P<raw>R"(?P<delim>[^(\s]*)\(.*?\)(?P=delim)")
      | (?P<string>(?:u8|u|U|L)?"(?:\\.|[^"\\\n])*")
      | (?P<char>(?:u8|u|U|L)?'(?:\\.|[^'\\\n])+')
      | (?P<number>\.?\d(?:[\w.']|[eEpP][+-])*)
      | (?P<ident>[A-Za-z_]\w*)
      | (?P<punct>::|->\*?|\.\.\.|<<=|>>=|&&|\|\||==|!=|<=|>=|\+\+|--|[-+*/%&|^!=<>]=?|[{}()\[\];,.?:~#])
      | (?P<other>.)""",
    re.VERBOSE | re.DOTALL,
)


@dataclass
class Token:
    text: str
    kind: str  # ident, number, string, punct
    line: int  # 0-based
    col: int


def tokenize(text: str) -> list[Token]:
    tokens: list[Token] = []
    line, line_start, pos = 0, 0, 0
    at_line_start = True  # only whitespace so far on this line: a '#' starts a preprocessor line
    while pos < len(text):
        m = TOKEN_RE.match(text, pos)
        assert m is not None
        kind = m.lastgroup if m.lastgroup != "delim" else "raw"
        value = m.group(0)
        if kind == "punct" and value == "#" and at_line_start:
            # A preprocessor line, with its backslash continuations: not C++ tokens.
            end = pos
            while True:
                end = text.find("\n", end)
                if end == -1:
                    end = len(text)
                    break
                if text[end - 1] != "\\":
                    break
                line += 1
                line_start = end + 1
                end += 1
            pos = end
            continue
        if kind in ("ident", "number", "string", "char", "raw", "punct", "other"):
            if kind in ("string", "char", "raw"):
                kind = "string"
            tokens.append(Token(value, kind, line, pos - line_start))
            at_line_start = False
        elif kind == "nl":
            at_line_start = True
        newlines = value.count("\n")
        if newlines:
            line += newlines
            line_start = pos + value.rfind("\n") + 1
        pos = m.end()
    return tokens


def matching(tokens: list[Token], index: int) -> int:
    """The index of the bracket that closes (or opens) tokens[index]."""
    pairs = {"(": ")", "[": "]", "{": "}"}
    opening = tokens[index].text
    if opening in pairs:
        closing, step = pairs[opening], 1
    else:
        closing = {v: k for k, v in pairs.items()}[opening]
        step = -1
    depth = 0
    i = index
    while 0 <= i < len(tokens):
        t = tokens[i].text
        if t == opening:
            depth += 1
        elif t == closing:
            depth -= 1
            if depth == 0:
                return i
        i += step
    raise ValueError("unbalanced brackets")


def split_top_level(tokens: list[Token], separator: str = ",") -> list[list[Token]]:
    """Splits on `separator` outside (), [], {} and template angle brackets."""
    parts: list[list[Token]] = [[]]
    depth = 0
    angle = 0
    for t in tokens:
        if t.text in "([{":
            depth += 1
        elif t.text in ")]}":
            depth -= 1
        elif t.text == "<" and depth == 0 and parts[-1] and parts[-1][-1].kind == "ident":
            angle += 1
        elif t.text == ">" and depth == 0 and angle > 0:
            angle -= 1
        elif t.text == ">>" and depth == 0 and angle > 0:
            angle = max(0, angle - 2)
        if t.text == separator and depth == 0 and angle == 0:
            parts.append([])
        else:
            parts[-1].append(t)
    return [p for p in parts if p]


def parameter_names(params: list[Token]) -> list[str]:
    """The names of a parameter list's named parameters (`const Ray& ray, int` gives ["ray"])."""
    names = []
    for part in split_top_level(params):
        # Drop a default argument and attributes.
        cut = [t for t in part]
        for i, t in enumerate(cut):
            if t.text == "=":
                cut = cut[:i]
                break
        while cut and cut[-1].text == "]":  # an array parameter: `int a[3]`
            cut = cut[: matching(cut, len(cut) - 1)]
        if len(cut) < 2:
            continue
        last, before = cut[-1], cut[-2]
        if last.kind != "ident" or last.text in KEYWORDS or before.text == "::":
            continue
        names.append(("..." if any(t.text == "..." for t in cut) else "") + last.text)
    return names


@dataclass
class Function:
    name: str
    parameters: list[str]
    body_open: int  # token index of the body's '{'
    body_close: int  # token index of its '}'


def enclosing_function(tokens: list[Token], line: int) -> Function | None:
    """The innermost function (or lambda) whose body is open on `line`."""
    stack: list[int] = []
    for i, t in enumerate(tokens):
        if t.line >= line:
            break
        if t.text == "{":
            stack.append(i)
        elif t.text == "}" and stack:
            stack.pop()
    for open_index in reversed(stack):
        i = skip_member_initialisers(tokens, open_index - 1)
        # Walk back over what may follow a parameter list: cv, ref and noexcept qualifiers, a trailing return
        # type, attributes, override/final.
        while i >= 0 and tokens[i].text != ")":
            if tokens[i].text in (";", "{", "}", "="):
                i = -1
                break
            if tokens[i].text == "]":
                i = matching(tokens, i)
            i -= 1
        if i < 0:
            continue
        close = i
        open_paren = matching(tokens, close)
        name_index = open_paren - 1
        if name_index < 0:
            continue
        name_token = tokens[name_index]
        if name_token.text == "]":
            name = "lambda"
        elif name_token.kind == "ident" and name_token.text not in ("if", "for", "while", "switch", "catch"):
            name = name_token.text
        elif name_token.kind == "punct":
            # operator() and friends: the word `operator` and what follows it.
            j = name_index
            while j >= 0 and tokens[j].text != "operator" and name_index - j < 4:
                j -= 1
            if j < 0 or tokens[j].text != "operator":
                continue
            name = "operator" + "".join(t.text for t in tokens[j + 1 : open_paren])
        else:
            continue
        return Function(name, parameter_names(tokens[open_paren + 1 : close]), open_index,
                        matching(tokens, open_index))
    return None


def skip_member_initialisers(tokens: list[Token], i: int) -> int:
    """From the token before a body's '{': past a constructor's `: a_(x), b_{y}` to the token before ':'."""
    j = i
    while j >= 1 and tokens[j].text in (")", "}"):
        start = matching(tokens, j)
        if start < 2 or tokens[start - 1].kind != "ident":
            return i
        before = tokens[start - 2].text
        if before == ":":
            return start - 3
        if before != ",":
            return i
        j = start - 3
    return i


def declared_locals(statement: list[Token]) -> list[str]:
    """The variables a block-scope statement declares (`const Vec2 corner{...};` gives ["corner"])."""
    if not statement or statement[0].text in STATEMENT_KEYWORDS or statement[0].kind != "ident":
        return []
    names = []
    for part_index, part in enumerate(split_top_level(statement)):
        j = 0
        depth = 0
        while j < len(part):
            t = part[j].text
            if t == "[" and depth == 0 and j > 0 and part[j - 1].text in ("auto", "&", "&&"):
                # A structured binding: auto [a, b] = ...
                close = matching(part, j)
                names += [x.text for x in part[j + 1 : close] if x.kind == "ident"]
                j = -1
                break
            if t in ("=", "{", "(", "[") and depth == 0:
                break
            if t == "<":
                depth += 1
            elif t == ">" and depth > 0:
                depth -= 1
            j += 1
        if j <= 0:
            continue
        name = part[j - 1]
        before = part[j - 2] if j >= 2 else None
        if name.kind != "ident" or name.text in KEYWORDS:
            continue
        if part_index == 0:
            # The first declarator needs a type before it: an identifier, a keyword type, '>', '&' or '*'.
            if before is None or before.text in (".", "->", "::") or (
                before.kind == "punct" and before.text not in (">", "&", "&&", "*", ">>")
            ):
                continue
        elif before is not None and before.text not in ("*", "&", "&&"):
            continue
        names.append(name.text)
    return names


def locals_before(tokens: list[Token], function: Function, line: int) -> list[str]:
    """Variables declared at the top level of the function body before `line`."""
    names: list[str] = []
    statement: list[Token] = []
    i = function.body_open + 1
    while i < function.body_close and tokens[i].line < line:
        t = tokens[i]
        if t.text == "{":
            close = matching(tokens, i)
            last = statement[-1] if statement else None
            if last and last.kind in ("ident", "punct") and last.text not in (")", "else", "do", "try"):
                # A braced initialiser: part of a declaration.
                statement += tokens[i : close + 1]
                i = close + 1
                continue
            statement = []  # a block of if/for/while/...: its declarations are not in scope after it
            i = close + 1
            continue
        if t.text == ";":
            names += declared_locals(statement)
            statement = []
        else:
            statement.append(t)
        i += 1
    return names


@dataclass
class Helper:
    name: str
    line: int
    col: int


def internal_helpers(tokens: list[Token]) -> list[Helper]:
    """Functions and variables with internal linkage at namespace scope (in an unnamed namespace or
    `static`): the compiler reports them when unused. Templates are left out (unused ones are not reported).
    """
    helpers = []
    anonymous: list[bool] = []  # the namespaces open here, and whether each is unnamed
    start = 0  # where the current namespace-scope declaration starts
    i = 0
    while i < len(tokens):
        t = tokens[i].text
        decl = tokens[start:i]
        texts = [x.text for x in decl]
        if t == "{":
            if texts and (texts[0] == "namespace" or texts[:2] == ["inline", "namespace"] or texts[0] == "extern"):
                anonymous.append(texts[-1] == "namespace")
                start = i + 1
                i += 1
                continue
            close = matching(tokens, i)
            is_function = "(" in texts and ("=" not in texts or texts.index("(") < texts.index("="))
            if is_function and texts[0] not in ("struct", "class", "union", "enum"):
                helper = _helper_of(decl, any(anonymous))  # a function definition: its body ends it
                if helper:
                    helpers.append(helper)
                start = close + 1
            i = close + 1  # a class body or a braced initialiser: the declaration goes on to its ';'
            continue
        if t == "}":
            if anonymous:
                anonymous.pop()
            start = i + 1
        elif t == ";":
            declares_function = "(" in texts and ("=" not in texts or texts.index("(") < texts.index("="))
            if texts and not declares_function:
                helper = _helper_of(decl, any(anonymous), variable=True)
                if helper:
                    helpers.append(helper)
            start = i + 1
        i += 1
    return helpers


def _helper_of(decl: list[Token], in_unnamed_namespace: bool, variable: bool = False) -> Helper | None:
    if not decl or decl[0].text in ("template", "using", "typedef", "namespace", "struct", "class", "enum",
                                   "union", "extern", "static_assert", "friend"):
        return None
    texts = [t.text for t in decl]
    if not (in_unnamed_namespace or "static" in texts):
        return None
    if variable:
        stop = next((k for k, x in enumerate(texts) if x in ("=", "{", "[")), len(texts))
    else:
        stop = texts.index("(")
    if stop == 0 or decl[stop - 1].kind != "ident" or decl[stop - 1].text in KEYWORDS:
        return None
    return Helper(decl[stop - 1].text, decl[0].line, decl[0].col)
