// Golden vectors: tests/vectors/vectors.json, the file the C++, command-line,
// Python and JavaScript tests all read. Frames and values there are worked out
// by hand from the protocol documents (each vector's "source" says where);
// nothing in it was produced by running robowire.
import { readFileSync } from 'node:fs';

export const data = JSON.parse(readFileSync(new URL('../../tests/vectors/vectors.json', import.meta.url), 'utf8'));

export function bytes(hex) {
  return Uint8Array.from(hex.split(/\s+/).filter(Boolean), (b) => parseInt(b, 16));
}

// An encode value as the package takes it: {"hex": "01 02"} is a Uint8Array.
export function value(v) {
  if (Array.isArray(v)) return v.map(value);
  if (v !== null && typeof v === 'object') {
    const keys = Object.keys(v);
    if (keys.length === 1 && keys[0] === 'hex') return bytes(v.hex);
    return Object.fromEntries(keys.map((k) => [k, value(v[k])]));
  }
  return v;
}

// BuWizz3: [direction, hex frame, message, fields that must match, encode fields]
export const cases = data.messages
  .filter((m) => m.protocol === 'buwizz3')
  .map((m) => [m.direction, m.hex, m.message, m.fields, value(m.encode)]);

// BuWizz3 status, 68 bytes (with the PID block)
export const status68 = data.messages.find((m) => m.protocol === 'buwizz3' && m.message === 'status').hex;
