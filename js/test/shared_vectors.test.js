// Every vector of tests/vectors/vectors.json (shared with the C++, command-line
// and Python tests) through each protocol the package exports: decode gives the
// message and its fields, encode gives the bytes, bad frames throw the code,
// offset and line. A protocol the package does not export is skipped, named.
import assert from 'node:assert/strict';
import { test } from 'node:test';

import * as robowire from '../index.js';
import { bytes, data, value } from './vectors.js';

const codec = (protocol) => robowire[protocol];
const missing = (protocol) => (codec(protocol) ? false : `the package exports no ${protocol}`);
const options = (v) => (v.direction ? { direction: v.direction } : {});

for (const v of data.messages) {
  test(`${v.protocol} ${v.message} ${v.hex.slice(0, 23)}`, { skip: missing(v.protocol) }, () => {
    const c = codec(v.protocol);
    const m = c.decode(bytes(v.hex), options(v));
    assert.equal(m.type, 'message');
    assert.equal(m.protocol, v.protocol);
    assert.equal(m.message, v.message);
    for (const [k, want] of Object.entries(v.fields)) assert.deepEqual(m.fields[k], want, k);
    assert.deepEqual(c.encode(v.message, value(v.encode)), bytes(v.hex));
    // other spellings: record fields left out are 0, enumerators as numbers
    for (const also of v.encode_also ?? []) assert.deepEqual(c.encode(v.message, value(also)), bytes(v.hex));
  });
}

for (const v of data.errors) {
  const name = `${v.protocol} error ${v.code} at ${v.offset}: ${v.hex.slice(0, 23)}`;
  test(name, { skip: missing(v.protocol) }, () => {
    assert.throws(() => codec(v.protocol).decode(bytes(v.hex), options(v)), (e) => {
      assert.ok(e instanceof robowire.RobowireError, `${e}`);
      assert.equal(e.message, v.error);
      assert.equal(e.code, v.code);
      assert.equal(e.offset, v.offset);
      assert.equal(e.field, v.field);
      assert.equal(e.messageName, v.message);
      return true;
    });
  });
}

// each frame of a multi-frame message decodes alone as a NAVBOT frame: the command, the frames still to come
for (const v of data.navbot_multiframe) {
  test(`navbot frames of ${v.text}`, { skip: missing('navbot') }, () => {
    v.frames.forEach((hex, i) => {
      const m = codec('navbot').decode(bytes(hex));
      assert.equal(m.message, 'frame');
      assert.equal(m.fields.command, v.command);
      assert.equal(m.fields.remaining, v.frames.length - 1 - i);
    });
  });
}
