// robowire for JavaScript: BuWizz3 messages decoded to the command-line
// tool's JSON and encoded from plain objects, by the C++ library compiled to
// WebAssembly (dist/robowire_wasm.mjs, built by ./build). docs/javascript.md.
import createModule from './dist/robowire_wasm.mjs';

const wasm = createModule();  // compiled synchronously (WASM_ASYNC_COMPILATION=0)
const utf8 = new TextEncoder();

// A message that cannot be decoded or encoded. `message`: the tool's error
// line; `code`: the error code's name ("value_out_of_range", or null for a
// usage error: unknown message or field, ambiguous direction, wrong count);
// `offset`: the byte (in the input for decode, in the frame for encode);
// `field`: the field at that byte ("colors.g" in a record) or null;
// `messageName`: the message it was read or written as, or null.
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

function text() {
  return wasm.UTF8ToString(wasm._rw_text());
}
function lastError() {
  const s = (p) => wasm.UTF8ToString(p) || null;
  const code = s(wasm._rw_error_code());
  return {
    code,
    offset: code === null ? null : wasm._rw_error_offset() >>> 0,
    field: s(wasm._rw_error_field()),
    messageName: s(wasm._rw_error_message()),
  };
}
// Strings as C strings, one after the other in the input scratch memory.
function cStrings(...strings) {
  const sizes = strings.map((s) => wasm.lengthBytesUTF8(s) + 1);
  let p = wasm._rw_input(sizes.reduce((a, b) => a + b, 0));
  return strings.map((s, i) => {
    wasm.stringToUTF8(s, p, sizes[i]);
    p += sizes[i];
    return p - sizes[i];
  });
}

const directions = { undefined: 0, command: 1, notification: 2 };

function decode(bytes, { direction } = {}) {
  if (!(bytes instanceof Uint8Array)) {
    if (bytes instanceof ArrayBuffer) bytes = new Uint8Array(bytes);
    else if (ArrayBuffer.isView(bytes)) bytes = new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    else throw new TypeError('decode: bytes must be a Uint8Array, ArrayBuffer or DataView');
  }
  const d = directions[direction];
  if (d === undefined) throw new TypeError(`decode: direction must be "command" or "notification", not ${JSON.stringify(direction)}`);
  const p = wasm._rw_input(bytes.length);
  wasm.HEAPU8.set(bytes, p);
  const status = wasm._rw_buwizz3_decode(p, bytes.length, d);
  if (status !== 0) throw new RobowireError(text(), lastError());
  return JSON.parse(text());
}

const layouts = new Map();
function layoutOf(message) {
  let l = layouts.get(message);
  if (l === undefined) {
    l = wasm._rw_buwizz3_layout(...cStrings(message)) === 0 ? JSON.parse(text()) : null;
    layouts.set(message, l);
  }
  return l;
}

function hexOf(bytes) {
  return Array.from(bytes, (b) => b.toString(16).padStart(2, '0')).join('');
}
// One scalar as the tool's encode reads it.
function scalar(v, path) {
  switch (typeof v) {
    case 'number':
    case 'bigint':
      return String(v);
    case 'boolean':
      return v ? 'true' : 'false';
    case 'string':
      return v;
    default:
      if (v instanceof Uint8Array) return hexOf(v);
      throw new TypeError(`encode: ${path}: a number, boolean or string expected, not ${v === null ? 'null' : typeof v}`);
  }
}
// A key decode adds (physical values, flag bits), which encode does not read.
function derived(name, fields) {
  return name.endsWith('_bits') || name.endsWith('_physical') || fields.some((x) => x.name === `${name}_raw`);
}
// A record's values in the tool's flattened order (keys not given: 0).
function flattenRecord(obj, fields, path, out) {
  if (obj === null || typeof obj !== 'object' || Array.isArray(obj))
    throw new TypeError(`encode: ${path}: an object expected`);
  const known = new Set(fields.map((f) => f.name));
  for (const k of Object.keys(obj))
    if (!known.has(k) && !derived(k, fields))
      throw new RobowireError(`unknown field ${path}.${k} (fields: ${[...known].join(', ')})`);
  for (const f of fields) flattenField(obj[f.name], f, `${path}.${f.name}`, out, true);
}
function flattenField(v, f, path, out, inRecord) {
  const zero = (n) => { for (let i = 0; i < n; ++i) out.push('0'); };
  const count = f.array ? f.count : 1;
  if (v === undefined && inRecord) {
    if (f.record) for (let i = 0; i < count; ++i) flattenRecord({}, f.record, path, out);
    else zero(count);
    return;
  }
  if (f.array && !(v instanceof Uint8Array)) {
    if (!Array.isArray(v)) throw new TypeError(`encode: ${path}: an array of ${f.count} expected`);
    if (inRecord && v.length !== f.count)
      throw new RobowireError(`${path}: ${v.length} values given, ${f.count} expected`);
    v.forEach((e, i) => (f.record ? flattenRecord(e, f.record, `${path}[${i}]`, out) : out.push(scalar(e, `${path}[${i}]`))));
  } else if (f.record) {
    flattenRecord(v, f.record, path, out);
  } else if (f.array) {
    for (const b of v) out.push(String(b));
  } else {
    out.push(scalar(v, path));
  }
}

function encode(message, fields = {}) {
  if (message !== null && typeof message === 'object') {  // what decode returns
    if (message.protocol !== undefined && message.protocol !== 'buwizz3')
      throw new RobowireError(`encode: a ${message.protocol} message, not buwizz3`);
    fields = message.fields ?? {};
    message = message.message;
  }
  if (typeof message !== 'string') throw new TypeError('encode: message must be a name (string)');
  if (fields === null || typeof fields !== 'object') throw new TypeError('encode: fields must be an object');
  const layout = layoutOf(message);
  const pairs = [];
  if (layout !== null) {
    for (const [name, v] of Object.entries(fields)) {
      if (v === undefined || v === null) continue;  // absent optional block
      const f = layout.find((x) => x.name === name);
      if (f === undefined) {  // decode's physical values and _bits are not read; other names are errors
        if (derived(name, layout)) continue;
        pairs.push(`${name}=`);
        continue;
      }
      const out = [];
      flattenField(v, f, name, out, false);
      pairs.push(`${name}=${out.join(',')}`);
    }
  }
  const status = wasm._rw_buwizz3_encode(...cStrings(message, pairs.join('\n')));
  if (status !== 0) {
    const e = lastError();
    if (layout !== null && e.messageName === null) e.messageName = message;
    throw new RobowireError(text(), e);
  }
  const p = wasm._rw_bytes();
  return wasm.HEAPU8.slice(p, p + wasm._rw_bytes_size());
}

// BuWizz3: decode(bytes, {direction}) -> {type, protocol, message, fields};
// encode(message, fields) -> Uint8Array. direction: "command" (host to
// device), "notification" (device to host) or absent (the command byte decides).
export const buwizz3 = Object.freeze({ decode, encode });
