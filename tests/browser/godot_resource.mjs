// A reader of Godot's text resources (.tres, .tscn), written from the
// format's documented grammar ("TSCN file format" in Godot's manual), strict
// enough to refuse what Godot's own parser would:
//   file      := section*
//   section   := '[' NAME (KEY '=' value)* ']' NEWLINE (KEY '=' value NEWLINE)*
//   value     := number | string | '&' string (StringName) | '^' string (NodePath)
//              | 'true' | 'false' | 'null' | NAME '(' (value (',' value)*)? ')'
//              | '[' (value (',' value)*)? ']' | '{' (value ':' value (',' ...)*)? '}'
//   string    := '"' (char | '\' ('"' | '\' | 'n' | 't' | 'r' | 'b' | 'f' | 'u' HEX4))* '"'
// A constructor comes back as { call: NAME, args: [...] }, a StringName as
// { stringName: text }, a NodePath as { nodePath: text }. Lines starting
// with ';' are comments.

const ESCAPES = { '"': '"', '\\': '\\', n: '\n', t: '\t', r: '\r', b: '\b', f: '\f' };

class Reader {
  constructor(text) {
    this.text = text;
    this.at = 0;
  }

  fail(what) {
    const line = this.text.slice(0, this.at).split('\n').length;
    throw new Error(`line ${line}: ${what} at ${JSON.stringify(this.text.slice(this.at, this.at + 30))}`);
  }

  // Spaces, tabs and, unless `inLine`, newlines and comment lines.
  skip(inLine = false) {
    for (;;) {
      const c = this.text[this.at];
      if (c === ' ' || c === '\t' || c === '\r' || (!inLine && c === '\n')) this.at += 1;
      else if (!inLine && c === ';' && (this.at === 0 || this.text[this.at - 1] === '\n')) {
        while (this.at < this.text.length && this.text[this.at] !== '\n') this.at += 1;
      } else return;
    }
  }

  expect(token) {
    this.skip();
    if (!this.text.startsWith(token, this.at)) this.fail(`expected ${token}`);
    this.at += token.length;
  }

  peek() {
    this.skip();
    return this.text[this.at];
  }

  name() {
    this.skip();
    const m = /^[A-Za-z_][A-Za-z0-9_/]*/.exec(this.text.slice(this.at));
    if (!m) this.fail('expected a name');
    this.at += m[0].length;
    return m[0];
  }

  string() {
    this.expect('"');
    let out = '';
    for (;;) {
      const c = this.text[this.at++];
      if (c === undefined) this.fail('unterminated string');
      if (c === '"') return out;
      if (c !== '\\') {
        out += c;
        continue;
      }
      const e = this.text[this.at++];
      if (e === 'u') {
        const hex = this.text.slice(this.at, this.at + 4);
        if (!/^[0-9a-fA-F]{4}$/.test(hex)) this.fail('bad \\u escape');
        out += String.fromCharCode(parseInt(hex, 16));
        this.at += 4;
      } else if (e in ESCAPES) out += ESCAPES[e];
      else this.fail(`unknown escape \\${e}`);
    }
  }

  list(close, item) {
    const items = [];
    if (this.peek() === close) {
      this.at += 1;
      return items;
    }
    for (;;) {
      items.push(item());
      const c = this.peek();
      this.at += 1;
      if (c === close) return items;
      if (c !== ',') this.fail(`expected , or ${close}`);
    }
  }

  value() {
    const c = this.peek();
    if (c === '"') return this.string();
    if (c === '&') { this.at += 1; return { stringName: this.string() }; }
    if (c === '^') { this.at += 1; return { nodePath: this.string() }; }
    if (c === '[') { this.at += 1; return this.list(']', () => this.value()); }
    if (c === '{') {
      this.at += 1;
      return Object.fromEntries(this.list('}', () => {
        const key = this.value();
        this.expect(':');
        return [typeof key === 'string' ? key : JSON.stringify(key), this.value()];
      }));
    }
    const number = /^-?(?:\d+\.?\d*(?:e[+-]?\d+)?|inf|nan)/.exec(this.text.slice(this.at));
    if (number) {
      this.at += number[0].length;
      return Number(number[0].replace('inf', 'Infinity').replace('nan', 'NaN'));
    }
    const name = this.name();
    if (name === 'true' || name === 'false') return name === 'true';
    if (name === 'null') return null;
    this.expect('(');
    return { call: name, args: this.list(')', () => this.value()) };
  }

  section() {
    this.expect('[');
    const tag = this.name();
    const fields = {};
    while (this.peek() !== ']') {
      const key = this.name();
      this.expect('=');
      fields[key] = this.value();
    }
    this.at += 1;
    const props = {};
    for (;;) {
      this.skip();
      if (this.at >= this.text.length || this.text[this.at] === '[') break;
      const key = this.name();
      this.expect('=');
      props[key] = this.value();
      this.skip(true);
      if (this.at < this.text.length && this.text[this.at] !== '\n') this.fail('expected the end of the line');
    }
    return { tag, fields, props };
  }
}

// The sections of a text resource, in order: { tag, fields, props }.
export function parseGodotResource(text) {
  const reader = new Reader(text);
  const sections = [];
  reader.skip();
  while (reader.at < text.length) {
    sections.push(reader.section());
    reader.skip();
  }
  return sections;
}
