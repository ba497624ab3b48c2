#!/usr/bin/env node
// Writes index.d.ts, the package's TypeScript declarations, from the tables
// (the JSON of `robowire list --json`): per message an interface of the
// decoded fields as `decode` returns them and one of the fields `encode`
// takes, and per protocol the union of its decoded messages.
//
//   node gen/dts.js                 schema.json if it exists, else $ROBOWIRE_CLI list --json
//   node gen/dts.js --schema F      the schema from file F
//   node gen/dts.js --stdout        print instead of writing index.d.ts
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync, writeFileSync } from 'node:fs';

const here = new URL('..', import.meta.url);

// The schema JSON: --schema F, js/schema.json, or the tool's `list --json`.
export function loadSchema(file) {
  if (file) return JSON.parse(readFileSync(file, 'utf8'));
  const committed = new URL('schema.json', here);
  if (existsSync(committed)) return JSON.parse(readFileSync(committed, 'utf8'));
  const cli = process.env.ROBOWIRE_CLI;
  if (!cli) throw new Error('dts: no js/schema.json and ROBOWIRE_CLI is not set');
  return JSON.parse(execFileSync(cli, ['list', '--json'], { encoding: 'utf8', maxBuffer: 64 << 20 }));
}

const pascal = (s) => s.split(/[_\s-]+/).filter(Boolean).map((w) => w[0].toUpperCase() + w.slice(1)).join('');
const lit = (s) => JSON.stringify(s);
const key = (s) => (/^[A-Za-z_$][\w$]*$/.test(s) ? s : lit(s));
const union = (xs) => xs.map(lit).join(' | ');
const maxTuple = 16;  // longer arrays are T[] (a 15-byte payload is still a tuple)

// The tool's rule for the physical value's key: x_raw -> x, else x_physical.
const physicalKey = (name) => (name.length > 4 && name.endsWith('_raw') ? name.slice(0, -4) : `${name}_physical`);

function arrayOf(t, f) {
  if (!f.array) return t;
  const simple = /^[\w.]+$/.test(t) ? t : `(${t})`;
  return f.count <= maxTuple ? `[${Array(f.count).fill(t).join(', ')}]` : `${simple}[]`;
}

function flagBitsType(f) {
  const members = f.flag_bits.map((b) => {
    let t;
    if (b.width === 1) t = 'boolean';
    else if (b.values.length === 2 ** b.width) t = union(b.values);
    else t = 'string';  // a value without a name prints as its number in a string
    return `${key(b.name)}: ${t}`;
  });
  return `{ ${members.join('; ')} }`;
}

// Per protocol: the record interfaces (by record name) and the message interfaces.
class Writer {
  constructor(protocol) {
    this.protocol = protocol;
    this.records = new Map();  // record name -> { decoded, input } type names
    this.out = [];
    this.used = new Set(['MessageName', 'Fields', 'Inputs', 'Message']);
  }

  // A type name (and its Input) not taken yet in this namespace.
  claim(name) {
    for (const n of [name, `${name}Input`]) {
      if (this.used.has(n)) throw new Error(`dts: ${this.protocol}: two types named ${n}`);
      this.used.add(n);
    }
  }

  recordNames(r) {
    let base = pascal(r.name);
    const sig = JSON.stringify(r.fields);
    for (let n = 2; ; n++) {
      const have = this.records.get(base);
      if (!have) break;
      if (have.sig === sig) return have;
      base = `${pascal(r.name)}${n}`;
    }
    this.claim(base);
    const names = { decoded: base, input: `${base}Input`, sig };
    this.records.set(base, names);
    this.out.push(...this.interfaces(names.decoded, names.input, r.fields, `record ${r.name}, ${r.size} bytes`, null));
    return names;
  }

  // The decoded and the input type of one element of field f.
  elementTypes(f) {
    switch (f.value) {
      case 'record': {
        const n = this.recordNames(f.record);
        return [n.decoded, `${n.input}`];
      }
      case 'bool': return ['boolean', 'boolean'];
      case 'enum': {
        const names = union(f.enum.map((e) => e.name));
        return [names, `${names} | number`];
      }
      case 'float': return ['number | null', 'number'];  // NaN and infinities decode as null
      case 'int': return ['number', 'number'];
      case 'text': return ['string', 'string'];
      case 'bytes': return ['string', 'string | Uint8Array'];  // hex text: "01 02 03"
      default: throw new Error(`dts: ${f.name}: unknown value kind ${f.value}`);
    }
  }

  field(f, message) {
    const [dec, inp] = this.elementTypes(f);
    const opt = f.optional ? ' | null' : '';
    const range = f.valid ? ` ${f.valid.min}..${f.valid.max}` : '';
    const unit = f.unit ? ` (x ${f.unit.scale}${f.unit.offset ? ` + ${f.unit.offset}` : ''} = ${f.unit.name})` : '';
    const doc = `/** ${f.type}${f.array ? `[${f.count}]` : ''} at byte ${f.offset}${range}${unit} */`;
    const d = [doc, `${key(f.name)}: ${arrayOf(dec, f)}${opt};`];
    const inputType = f.value === 'record' ? `Partial<${inp}>` : inp;
    const i = [`${key(f.name)}?: ${arrayOf(inputType, f)}${opt};`];
    if (f.value === 'int' && f.unit) {
      const v = f.array ? arrayOf('number', f) : 'number';
      d.push(`${key(physicalKey(f.name))}: { value: ${v}; unit: ${lit(f.unit.name)} }${opt};`);
    }
    if (f.value === 'int' && !f.array && f.flag_bits && f.flag_bits.length) {
      d.push(`${key(`${f.name}_bits`)}: ${flagBitsType(f)}${opt};`);
    }
    if (this.protocol === 'navbot' && message === 'frame' && f.name === 'payload') {
      d.push('/** the payload as text, up to its first zero byte: frames of the JSON command only */', 'payload_text?: string;');
    }
    return [d, i];
  }

  interfaces(decodedName, inputName, fields, what, message) {
    const d = [];
    const i = [];
    for (const f of fields) {
      const [fd, fi] = this.field(f, message);
      d.push(...fd);
      i.push(...fi);
    }
    const body = (lines) => lines.map((l) => `    ${l}`).join('\n');
    return [
      `  /** ${what}: as decode returns it */`,
      d.length ? `  interface ${decodedName} {\n${body(d)}\n  }` : `  interface ${decodedName} {}`,
      `  /** ${what}: what encode takes (absent: 0 or the first enum value) */`,
      i.length ? `  interface ${inputName} {\n${body(i)}\n  }` : `  interface ${inputName} {}`,
    ];
  }

  protocolBlock(p) {
    const ns = pascal(p.name);
    const names = [];
    for (const m of p.messages) {
      const n = pascal(m.name);
      this.claim(n);
      names.push([m.name, n]);
      const size = m.min_size === m.max_size ? `${m.min_size} byte${m.min_size === 1 ? '' : 's'}` : `${m.min_size}..${m.max_size} bytes`;
      const dir = m.direction ? `, ${m.direction}` : '';
      this.out.push(...this.interfaces(n, `${n}Input`, m.fields, `${m.name} (${size}${dir})`, m.name));
    }
    const msg = names.map(([m, n]) => `    | { type: 'message'; protocol: ${lit(p.name)}; message: ${lit(m)}; fields: ${n}; notes?: string[] }`);
    return [
      `/** ${p.name}: ${p.summary} */`,
      `export namespace ${ns} {`,
      ...this.out,
      `  /** The message names. */`,
      `  type MessageName = ${names.map(([m]) => lit(m)).join(' | ')};`,
      `  /** The decoded fields of each message. */`,
      `  interface Fields {\n${names.map(([m, n]) => `    ${key(m)}: ${n};`).join('\n')}\n  }`,
      `  /** The fields encode takes for each message. */`,
      `  interface Inputs {\n${names.map(([m, n]) => `    ${key(m)}: ${n}Input;`).join('\n')}\n  }`,
      `  /** A decoded message: tell them apart by \`message\`. */`,
      `  type Message =\n${msg.join('\n')};`,
      `}`,
    ].join('\n');
  }
}

export function generate(schema) {
  const protocols = schema.protocols.map((p) => p.name);
  for (const want of ['buwizz3', 'navbot', 'osp']) {
    if (!protocols.includes(want)) throw new Error(`dts: the schema has no ${want}`);
  }
  const blocks = schema.protocols.map((p) => new Writer(p.name).protocolBlock(p));
  const errors = union(schema.errors.map((e) => e.name).filter((n) => n !== 'ok'));
  return `// robowire: TypeScript declarations. Generated by gen/dts.js from the tables
// (robowire list --json, schema format ${schema.schema_version ?? schema.format}); do not edit.

/** Bytes in: a Web Bluetooth notification's DataView as is. */
export type Bytes = Uint8Array | ArrayBuffer | DataView;

/** BuWizz3 only: 'command' (host to device), 'notification' (device to host); absent: the command byte decides. */
export type Direction = 'command' | 'notification';
export interface DecodeOptions {
  direction?: Direction;
}

/** The error codes' names (robowire list --json's errors). */
export type ErrorCode = ${errors};

/** Bytes that are not a valid message, or values that cannot be encoded. */
export declare class RobowireError extends Error {
  constructor(message: string, parts?: { code?: ErrorCode | null; offset?: number | null; field?: string | null; messageName?: string | null });
  /** The error code's name, or null for a usage error (unknown message or field, wrong array length, ambiguous direction). */
  code: ErrorCode | null;
  /** The byte: in the input for decode, in the frame for encode. */
  offset: number | null;
  /** The field at that byte ("colors.g" in a record), or null. */
  field: string | null;
  /** The message it was read or written as, or null. */
  messageName: string | null;
}

${blocks.join('\n\n')}

/** A protocol's decoder and encoder. */
export interface Codec<M extends { message: string }, Inputs> {
  /** The message in bytes, as \`robowire decode <protocol> --json\` prints it. Throws RobowireError. */
  decode(bytes: Bytes, options?: DecodeOptions): M;
  /** The frame of \`message\` from its fields (absent: 0). Throws RobowireError. */
  encode<N extends keyof Inputs & string>(message: N, fields?: Inputs[N]): Uint8Array;
  /** The frame of a message as decode returns it. */
  encode(decoded: M): Uint8Array;
}

/** A record of a stream: a message as decode returns it, or a frame that could not be decoded. */
export interface StreamError<P extends string> {
  type: 'error';
  protocol: P;
  /** The tool's error line. */
  error: string;
  /** The frame as hex text. */
  bytes?: string;
  code?: ErrorCode | null;
  offset?: number | null;
  field?: string | null;
}

/** One GATT characteristic: its UUID and which way it carries messages. */
export interface Characteristic {
  readonly uuid: string;
  readonly direction: 'to_device' | 'from_device' | 'both';
  readonly what: string;
}

/** What a BuWizz3 advertisement (and scan response) says. */
export interface Buwizz3Advertisement {
  mode: 'application' | 'bootloader' | 'unknown';
  /** Application mode: the firmware version bytes x y (3.22 advertises [3, 0x22]); [0, 0] otherwise. */
  firmware_version: [number, number];
  /** Low 16 bits of the serial number. */
  serial_low16: number;
  has_manufacturer_data: boolean;
  has_service_uuid: boolean;
  local_name: string | null;
}

export interface Buwizz3Helpers {
  /** Motor power -127..127 for -100..100 % (half away from zero: 50 -> 64). RangeError outside -100..100. */
  powerFromPercent(percent: number): number;
  /** Percent of full power for a raw power -128..127 (raw x 100 / 127). */
  percentFromPower(raw: number): number;
  /** The service UUID and the characteristics (uart[0]: port 1). */
  readonly uuids: {
    readonly service: string;
    readonly application: Characteristic;
    readonly bootloader: Characteristic;
    readonly uart: readonly [Characteristic, Characteristic, Characteristic, Characteristic];
  };
  /** A BuWizz3's advertising data as raw AD structures, or null when it is not one. Throws RobowireError (bad_length). */
  parseAdvertisement(advertisement: Bytes, scanResponse?: Bytes | null): Buwizz3Advertisement | null;
}

export declare const buwizz3: Codec<Buwizz3.Message, Buwizz3.Inputs> & Buwizz3Helpers;

/** A NAVBOT reassembler's record for one frame (as \`robowire scan navbot --json\` prints it). */
export type NavbotRecord =
  | Navbot.Message
  | StreamError<'navbot'>
  | {
      type: 'reassembly';
      outcome: 'need_more' | 'complete' | 'single' | 'duplicate' | 'restarted' | 'discarded' | 'error';
      command?: number;
      text?: string;
      json_object?: boolean;
      error?: string;
    };

export declare const navbot: Codec<Navbot.Message, Navbot.Inputs> & {
  /** Collects the 20-byte frames of multi-frame messages. */
  Reassembler: new () => { push(frame: Bytes): NavbotRecord[] };
  /** The 20-byte frames of one message. */
  fragment<N extends keyof Navbot.Inputs & string>(message: N, fields?: Navbot.Inputs[N]): Uint8Array[];
  fragment(payload: Bytes | string, options?: { command?: number }): Uint8Array[];
};

/** An OSP scanner's counters (as \`robowire scan osp --json\`'s counters line). */
export interface OspCounters {
  frames: number;
  skipped_bytes: number;
  false_starts: number;
}

export declare const osp: Codec<Osp.Message, Osp.Inputs> & {
  /** Finds and decodes OSP frames in a serial byte stream, in chunks of any size. */
  Scanner: new () => { push(bytes: Bytes): Array<Osp.Message | StreamError<'osp'>>; readonly counters: OspCounters };
};

/** The tables, as \`robowire list --json\` prints them. */
export declare const schema: {
  format: number;
  protocols: Array<{ name: string; summary: string; messages: Array<{ name: string; direction: Direction | null; fields: unknown[] }> }>;
  errors: Array<{ code: number; name: string; text: string }>;
};
`;
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const args = process.argv.slice(2);
  const at = args.indexOf('--schema');
  const text = generate(loadSchema(at >= 0 ? args[at + 1] : undefined));
  if (args.includes('--stdout')) process.stdout.write(text);
  else writeFileSync(new URL('index.d.ts', here), text);
}
