// What the generated codecs (buwizz3.js, navbot.js, osp.js) share: the
// error class, error lines, hex text and number printing. Hand-written.

// A message that cannot be decoded or encoded. `message`: the command-line
// tool's error line; `code`: the error code's name ("value_out_of_range"; null
// for a usage error); `offset`: the byte; `field`: the field at that byte or
// null; `messageName`: the message it was read or written as, or null.
export class RobowireError extends Error {
  constructor(text, { code = null, offset = null, field = null, messageName = null } = {}) {
    super(text);
    this.name = 'RobowireError';
    this.code = code;
    this.offset = offset;
    this.field = field;
    this.messageName = messageName;
  }
}

const HEX = Array.from({ length: 256 }, (_, i) => i.toString(16).toUpperCase().padStart(2, '0'));
// Upper-case hex, a space between bytes (tail fields): "0B 0C 0D".
export function hex(b, from = 0, to = b.length) {
  const parts = [];
  for (let i = from; i < to; ++i) parts.push(HEX[b[i]]);
  return parts.join(' ');
}
// A physical value: rounded to 15 significant digits (13.000000000000002 -> 13).
export function tidy(v) {
  return Number.isFinite(v) ? Number(v.toPrecision(15)) : null;
}
// An f32 value: the float as is; NaN and infinity: null.
export function f32(dv, o) {
  const v = dv.getFloat32(o, true);
  return Number.isFinite(v) ? v : null;
}
const utf8 = new TextDecoder('utf-8');
// Text of bytes [from, to) (invalid UTF-8: U+FFFD).
export function text(b, from, to) {
  return utf8.decode(b.subarray(from, to));
}
// Bytes as a Uint8Array over the same memory.
export function bytesOf(x) {
  if (x instanceof Uint8Array) return x;
  if (x instanceof ArrayBuffer) return new Uint8Array(x);
  if (ArrayBuffer.isView(x)) return new Uint8Array(x.buffer, x.byteOffset, x.byteLength);
  throw new TypeError('decode: bytes must be a Uint8Array, ArrayBuffer or DataView');
}

// An error of message `m` (its generated info: name, lengths text, fields as
// [offset, end, name, ranged, min, max, unit suffix]) at byte `offset`.
export class Fail {
  constructor(code, offset) {
    this.code = code;
    this.offset = offset;
  }
}
export function fail(code, offset) {
  throw new Fail(code, offset);
}
export function messageError(errors, m, code, offset) {
  const length = code === 'too_short' || code === 'too_long';
  let f = null;
  for (const x of m.fields) {
    if (x[0] === x[1] ? offset === x[0] : offset >= x[0] && offset < x[1]) {
      f = x;
      break;
    }
  }
  let line = m.name;
  if (f && !length) line += `.${f[2]}`;
  line += `: ${errors[code]}`;
  if (length || code === 'bad_length') line += ` (${m.lengths})`;
  if (f && f[3] && code === 'value_out_of_range') line += ` (valid ${f[4]}..${f[5]}${f[6]})`;
  line += ` at byte ${offset}`;
  return new RobowireError(line, { code, offset, field: f && !length ? f[2] : null, messageName: m.name });
}
export function keyError(errors, key, code, offset) {
  let line = 'unknown key';
  for (const k of key) line += ` 0x${k.toString(16).toUpperCase().padStart(2, '0')}`;
  if (code !== 'unknown_message') line += `: ${errors[code]}`;
  return new RobowireError(`${line} at byte ${offset}`, { code, offset });
}
export function plainError(errors, code, offset) {
  return new RobowireError(`${errors[code]} at byte ${offset}`, { code, offset });
}

// ---- encode: what the generated encoders (e0, e1, ... in each protocol's
// module) call off their fast path: the errors, and values that are not
// plain numbers.
const utf8out = new TextEncoder();
// A value at byte `o` that the tables reject; `field`: the value's path.
export function bad(errors, m, code, o, path) {
  throw Object.assign(messageError(errors, m, code, o), { field: path });
}
export function notInteger(v, path) {
  throw new TypeError(`encode: ${path}: an integer expected, not ${String(v)}`);
}
// An integer field's raw value from what is not a number: not given, the
// first enum value or 0; a boolean, 1 or 0; an enum name, its value (NaN
// for a name the enum lacks); else Number(v), which must be an integer.
export function rawOf(v, names, path) {
  let raw;
  if (v === undefined) raw = names ? Object.values(names)[0] ?? 0 : 0;
  else if (typeof v === 'boolean') raw = v ? 1 : 0;
  else if (typeof v === 'string' && names) {
    raw = names[v];
    if (raw === undefined) return NaN;
  } else raw = Number(v);
  if (!Number.isInteger(raw)) notInteger(v, path);
  return raw;
}
// An integer field's value that is not a valid number as it is: its raw
// value (rawOf), checked against the enum's values (numbers: value -> 1)
// or min..max; throws for a value the field cannot hold.
export function intSlow(v, names, numbers, min, max, errors, m, o, path) {
  let raw;
  if (typeof v !== 'number') raw = rawOf(v, names, path);
  else if (!Number.isInteger(v)) notInteger(v, path);
  else raw = v;
  if (numbers ? numbers[raw] === undefined : raw < min || raw > max)
    bad(errors, m, numbers ? 'invalid_enum' : 'value_out_of_range', o, path);
  return raw;
}
export function notObject(path) {
  throw new TypeError(`encode: ${path}: an object expected`);
}
export function notArray(path, count) {
  throw new TypeError(`encode: ${path}: an array of ${count} expected`);
}
export function badCount(m, path, length, count, top) {
  throw new RobowireError(`${path}: ${length} values given, ${count} expected${top ? ` (${path}=v1,...,v${count})` : ''}`,
    { messageName: m.name, field: path });
}
export function unknownField(m, path, key, names) {
  throw new RobowireError(`unknown field ${path ? `${path}.` : ''}${key} (fields: ${names})`, { messageName: m.name });
}
// Writes text field v (a string; not given: empty) at o; true when it does not fit.
export function putText(out, v, o, capacity, path) {
  if (v === undefined || v === null) v = '';
  if (typeof v !== 'string') throw new TypeError(`encode: ${path}: text expected`);
  const t = utf8out.encode(v);
  if (t.length > capacity || t.includes(0)) return true;
  out.set(t, o);
  return false;
}
// A byte tail's bytes: a Uint8Array, an array or hex text.
export function tailBytes(v) {
  if (v === undefined || v === null) return new Uint8Array(0);
  if (typeof v === 'string') {
    const s = v.replace(/\s+/g, '');
    if (!/^([0-9a-fA-F]{2})*$/.test(s)) throw new TypeError('encode: bytes as hex text expected');
    return Uint8Array.from(s.match(/../g) ?? [], (x) => parseInt(x, 16));
  }
  return Uint8Array.from(v);
}
// encode(message, fields) or encode(decoded): the message's encoder (index:
// name -> its number in encoders).
export function encodeWith(protocol, index, encoders, message, fields = {}) {
  if (message !== null && typeof message === 'object') {  // what decode returns
    if (message.protocol !== undefined && message.protocol !== protocol)
      throw new RobowireError(`encode: a ${message.protocol} message, not ${protocol}`);
    fields = message.fields ?? {};
    message = message.message;
  }
  if (typeof message !== 'string') throw new TypeError('encode: message must be a name (string)');
  if (fields === null || typeof fields !== 'object') throw new TypeError('encode: fields must be an object');
  const i = index.get(message);
  if (i === undefined) throw new RobowireError(`unknown message ${message} (robowire list ${protocol})`);
  return encoders[i](fields);
}

// ---- serial streams: frames found in a byte stream (OSP's scanner)
// A frame: `size` bytes with fixed bytes [[offset, value]...], the first at 0.
// A candidate that breaks a fixed byte is dropped up to the next start byte.
export class FrameScanner {
  constructor(size, fixed, decode, protocol) {
    this.size = size;
    this.fixed = fixed;
    this.decodeFrame = decode;
    this.protocol = protocol;
    this.buf = new Uint8Array(size);
    this.len = 0;
    this.counters = { frames: 0, skipped_bytes: 0, false_starts: 0 };
  }
  partialOk() {
    for (const [o, v] of this.fixed) if (o < this.len && this.buf[o] !== v) return false;
    return true;
  }
  resync() {
    const start = this.fixed[0][1];
    for (;;) {
      ++this.counters.false_starts;
      let from = 1;
      while (from < this.len && this.buf[from] !== start) ++from;
      this.counters.skipped_bytes += from;
      this.buf.copyWithin(0, from, this.len);
      this.len -= from;
      if (this.partialOk()) return;
    }
  }
  // Feeds bytes; returns the records of the frames they complete: decoded
  // messages, or {type:'error', error, protocol, bytes} (as `robowire scan`).
  push(bytes) {
    const b = bytesOf(bytes);
    const out = [];
    const start = this.fixed[0][1];
    for (let i = 0; i < b.length; ++i) {
      const x = b[i];
      if (this.len === 0) {
        if (x === start) this.buf[this.len++] = x;
        else ++this.counters.skipped_bytes;
        continue;
      }
      const k = this.len++;
      this.buf[k] = x;
      const f = this.fixed.find(([o]) => o === k);
      if (f && f[1] !== x) {
        this.resync();
      } else if (k === this.size - 1) {
        this.len = 0;
        ++this.counters.frames;
        const frame = this.buf.slice();
        try {
          out.push(this.decodeFrame(frame));
        } catch (e) {
          if (!(e instanceof RobowireError)) throw e;
          out.push({ type: 'error', error: e.message, protocol: this.protocol, bytes: hex(frame) });
        }
      }
    }
    return out;
  }
}

// ---- messages over several fixed-size frames (NAVBOT): the library's
// reassembler (navbot/multiframe.hpp) and what `robowire scan` says of each frame.
const outcomeText = {
  need_more: 'part of a message, more frames to come',
  complete: 'message complete',
};
// The lines of a message's frames, as the tool writes them: a range where they
// follow each other ("4-5", "2, 4", "2-4, 6"); of more than 8 runs the first 3,
// "..." and the last.
function lineList(lines) {
  const runs = [];
  for (const n of lines) {
    if (runs.length && n === runs[runs.length - 1][1] + 1) runs[runs.length - 1][1] = n;
    else runs.push([n, n]);
  }
  const shown = runs.length > 8 ? [...runs.slice(0, 3), null, runs[runs.length - 1]] : runs;
  return (lines.length === 1 ? 'line ' : 'lines ') +
    shown.map((r) => (r === null ? '...' : r[0] === r[1] ? `${r[0]}` : `${r[0]}-${r[1]}`)).join(', ');
}

// The frame layout: command, remaining and payload offsets, payload size.
export class FrameReassembler {
  constructor(layout, decode, decodeFrame, protocol, errors) {
    Object.assign(this, { layout, decodeMessage: decode, decodeFrame, protocol, errors });
    this.buf = [];
    this.state = 'idle';
    this.last = null;  // the last frame of a multi-frame message: [command, remaining, payload hex]
    this.lastRemaining = 0;
    this.command = 0;
    this.skipping = false;
    this.skipCommand = 0;
    this.pushes = 0;
    this.lines = [];  // frames (push numbers) of the message in progress
    this.seenRemaining = 0;
    this.counters = { messages_reassembled: 0, duplicates: 0, restarted: 0, discarded: 0, reassembly_errors: 0 };
  }
  // Pushes one frame; returns its records as `robowire scan navbot --json`
  // prints them ("line": the frame's number, from 1): the decoded message or
  // its error, then what reassembly says of it (none for a one-frame message).
  push(bytes) {
    const b = bytesOf(bytes);
    const line = ++this.pushes;
    const out = [];
    try {
      out.push(this.decodeMessage(b));
    } catch (e) {
      if (!(e instanceof RobowireError)) throw e;
      const h = hex(b);
      out.push({ type: 'error', error: e.message, protocol: this.protocol,
        bytes: h.length > 200 ? `${h.slice(0, 200)} ... (${h.length} characters)` : h });
    }
    let f;
    try {
      f = this.decodeFrame(b);
    } catch (e) {
      if (!(e instanceof RobowireError)) throw e;
      return out;
    }
    const { command: co, remaining: ro, payload: po, payload_size: ps } = this.layout;
    const frame = { command: b[co], remaining: b[ro], payload: b.slice(po, po + ps) };
    const r = this.step(frame);
    const before = this.seenRemaining;
    this.seenRemaining = frame.remaining;
    const rec = { type: 'reassembly' };
    if (typeof r !== 'string') {
      ++this.counters.reassembly_errors;
      let dropped = '';
      if (this.lines.length)
        dropped = `; the partial message (${lineList(this.lines)}) is dropped`;
      this.lines = [];
      if (frame.remaining !== 0 && r.code === 'command_changed') this.lines.push(line);
      let note = `${this.errors[r.code]} at byte ${r.offset}`;
      if (r.code === 'bad_sequence') note += `: remaining ${frame.remaining} after ${before}, frames were lost`;
      if (r.code === 'command_changed') note += ': a frame of another multi-frame message';
      rec.outcome = 'error';
      rec.error = note + dropped;
    } else {
      rec.outcome = r;
      if (r === 'need_more') this.lines.push(line);
      else if (r === 'restarted') { ++this.counters.restarted; this.lines = [line]; }
      else if (r === 'duplicate') ++this.counters.duplicates;
      else if (r === 'discarded') ++this.counters.discarded;
      else if (r === 'complete') {
        this.lines.push(line);
        if (this.lines.length < 2) {
          this.lines = [];
          return out;
        }
        ++this.counters.messages_reassembled;
        let n = this.buf.length;
        while (n > 0 && this.buf[n - 1] === 0) --n;
        const t = Uint8Array.from(this.buf.slice(0, n));
        rec.command = frame.command;
        rec.lines = this.lines;
        rec.text = text(t, 0, t.length);
        rec.json_object = jsonObject(t);
        this.lines = [];
      }
    }
    out.push(rec);
    return out;
  }
  same(f) {
    const l = this.last;
    return l !== null && l.command === f.command && l.remaining === f.remaining && l.payload.every((x, i) => x === f.payload[i]);
  }
  step(f) {
    if (this.same(f)) return 'duplicate';
    if (this.state === 'complete') { this.state = 'idle'; this.buf = []; }
    if (this.skipping && f.command === this.skipCommand) {
      if (f.remaining === 0) this.skipping = false;
      this.last = f;
      return 'discarded';
    }
    if (this.state === 'idle') return this.start(f);
    if (f.command !== this.command) {
      if (f.remaining === 0) return 'single';
      const broken = this.command;
      const st = this.start(f);
      if (typeof st !== 'string') return st;
      this.skipping = true;
      this.skipCommand = broken;
      return new Fail('command_changed', 2);
    }
    if (f.remaining >= this.lastRemaining) {
      const st = this.start(f);
      return typeof st !== 'string' ? st : 'restarted';
    }
    if (f.remaining + 1 !== this.lastRemaining) {
      this.state = 'idle';
      this.buf = [];
      this.last = f;
      if (f.remaining !== 0) { this.skipping = true; this.skipCommand = f.command; }
      return new Fail('bad_sequence', 3);
    }
    return this.append(f);
  }
  start(f) {
    this.state = 'idle';
    this.buf = [];
    this.command = f.command;
    return this.append(f);  // 256 frames of 15 bytes fit: remaining is one byte
  }
  append(f) {
    for (const x of f.payload) this.buf.push(x);
    if (f.remaining !== 0 || this.buf.length > f.payload.length) this.last = f;
    this.lastRemaining = f.remaining;
    this.state = f.remaining === 0 ? 'complete' : 'collecting';
    return f.remaining === 0 ? 'complete' : 'need_more';
  }
}
// Whether `t` is one whole JSON object (the library's json_object: a structural check).
function jsonObject(t) {
  const space = (c) => c === 0x20 || c === 0x09 || c === 0x0a || c === 0x0d;
  let i = 0;
  while (i < t.length && space(t[i])) ++i;
  if (i === t.length || t[i] !== 0x7b) return false;
  const open = [];
  let inString = false;
  for (; i < t.length; ++i) {
    const c = t[i];
    if (inString) {
      if (c === 0x5c) ++i;
      else if (c === 0x22) inString = false;
      else if (c < 0x20) return false;
      continue;
    }
    if (c === 0x22) inString = true;
    else if (c === 0x7b || c === 0x5b) {
      if (open.length === 64) return false;
      open.push(c === 0x7b ? 0x7d : 0x5d);
    } else if (c === 0x7d || c === 0x5d) {
      if (open.length === 0 || open[open.length - 1] !== c) return false;
      open.pop();
      if (open.length === 0) break;
    }
  }
  if (open.length !== 0 || i >= t.length) return false;
  for (let k = i + 1; k < t.length; ++k) if (!space(t[k])) return false;
  return true;
}
// The frames of one message: `remaining` counts down to 0, the last frame zero-padded.
export function fragmentPayload(layout, fixed, command, payload) {
  const ps = layout.payload_size;
  const count = payload.length === 0 ? 1 : Math.ceil(payload.length / ps);
  if (count > 256) throw new RobowireError(`capacity exceeded at byte ${256 * ps}`, { code: 'capacity_exceeded', offset: 256 * ps });
  const frames = [];
  for (let i = 0; i < count; ++i) {
    const f = new Uint8Array(layout.size);
    for (const [o, v] of fixed) f[o] = v;
    f[layout.command] = command;
    f[layout.remaining] = count - 1 - i;
    f.set(payload.subarray(i * ps, i * ps + ps), layout.payload);
    frames.push(f);
  }
  return frames;
}
