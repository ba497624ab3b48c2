#!/usr/bin/env node
// Writes js/lib/<protocol>.js for every protocol of a schema (`robowire list
// --json`, js/schema.json): a straight-line decoder per message (no eval, no
// new Function) and the tables encode reads. Node, no dependencies.
//   node gen/generate.js [schema.json] [out dir]
import { readFileSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const J = JSON.stringify;
const full = {
  u8: [0, 255], i8: [-128, 127], u16le: [0, 65535], i16le: [-32768, 32767],
  u32le: [0, 4294967295], i32le: [-2147483648, 2147483647],
};
function read(f, o) {
  switch (f.type) {
    case 'u8': return `b[${o}]`;
    case 'i8': return `(b[${o}]<<24>>24)`;
    case 'u16le': return `(b[${o}]|b[${o + 1}]<<8)`;
    case 'i16le': return `((b[${o}]|b[${o + 1}]<<8)<<16>>16)`;
    case 'u32le': return `dv.getUint32(${o},true)`;
    case 'i32le': return `dv.getInt32(${o},true)`;
    case 'f32le': return `f32(dv,${o})`;
    case 'bits': return `((b[${o}]>>${f.bits.lo})&${(1 << f.bits.width) - 1})`;
    default: throw new Error(`generate: ${f.name}: no reader for ${f.type}`);
  }
}
function fullRange(f) {
  return f.type === 'bits' ? [0, (1 << f.bits.width) - 1] : full[f.type];
}

// Statements that set `${target}` to field f's value (base: the record's offset).
class Body {
  constructor() { this.lines = []; this.n = 0; }
  tmp() { return `v${this.n++}`; }
  push(s) { this.lines.push(s); }
}
function element(body, f, o) {
  // returns an expression of the element at byte o (after its checks)
  if (f.type === 'record') return recordExpr(body, f.record.fields, o);
  if (f.type === 'text') {
    const v = body.tmp();
    body.push(`let ${v}=${o};while(${v}<${o + f.capacity}&&b[${v}]!==0)++${v};` +
      `for(let i=${v};i<${o + f.capacity};++i)if(b[i]!==0)fail('bad_padding',i);`);
    return `text(b,${o},${v})`;
  }
  if (f.type === 'tail') return `hex(b,${o},Math.min(n,${o + f.capacity}))`;
  const raw = read(f, o);
  if (f.type === 'f32le') return raw;
  const v = body.tmp();
  body.push(`const ${v}=${raw};`);
  if (f.enum) {
    const names = {};
    for (const e of f.enum) names[e.value] = e.name;
    const t = `EN${enumTables.push(names) - 1}`;
    body.push(`if(${t}[${v}]===undefined)fail('invalid_enum',${o});`);
    return `${t}[${v}]`;
  }
  const [lo, hi] = fullRange(f);
  if (f.valid && (f.valid.min > lo || f.valid.max < hi)) {
    const c = [];
    if (f.valid.min > lo) c.push(`${v}<${f.valid.min}`);
    if (f.valid.max < hi) c.push(`${v}>${f.valid.max}`);
    body.push(`if(${c.join('||')})fail('value_out_of_range',${o});`);
  }
  if (f.value === 'bool') return `${v}!==0`;
  return v;
}
let enumTables = [];
let flagValues = [];  // the names of multi-bit flag values, one constant each
// Fields of a record as one object literal (optional blocks and the text
// of a JSON payload added after it: keys present only with their block).
function recordExpr(body, fields, base) {
  const obj = body.tmp();
  const entries = [];  // [key, expression] of the literal
  const after = [];    // statements run once the object exists
  const tail = [];     // [key, 'null'] of optional blocks, in the literal (no shape change when set)
  // optional blocks as keys of the literal (null, set when present): when
  // each is one key and no text key follows, the key order stays the same
  const inLiteral = !fields.some((f) => f.as_text_when) &&
    fields.filter((f) => f.optional).every((f) => !f.physical && !(f.flag_bits && !f.array && f.value === 'int'));
  for (const f of fields) {
    const o = base + f.offset;
    const key = J(f.name);
    const inner = new Body();
    inner.n = body.n;
    const vals = [];
    for (let i = 0; i < f.count; ++i) vals.push(element(inner, f, o + i * f.element_size));
    const value = f.array ? `[${vals.join(',')}]` : vals[0];
    const own = [];  // [key, expression] of this field
    if (f.physical || (f.flag_bits && !f.array && f.value === 'int')) {
      const pv = inner.tmp();
      inner.push(`const ${pv}=${value};`);
      own.push([key, pv]);
      if (f.physical) {
        const u = f.unit;
        // an integer times 1 plus 0 is exact: no rounding to do
        const phys = (x) => (u.scale === 1 && u.offset === 0 ? x : `tidy(${x}*${u.scale}+${u.offset})`);
        own.push([J(f.physical), `{value:${f.array ? `${pv}.map((x)=>${phys('x')})` : phys(pv)},unit:${J(u.name)}}`]);
      }
      if (f.flag_bits && !f.array) own.push([J(`${f.name}_bits`), bitsOf(f, pv)]);
    } else {
      own.push([key, value]);
    }
    body.n = inner.n;
    if (f.optional && inLiteral) {
      tail.push([key, 'null']);
      after.push(`if(n>${o}){if(n<${o + f.size})fail('bad_length',${o});`,
        ...inner.lines, ...own.map(([k, v]) => `${obj}[${k}]=${v};`), '}');
    } else if (f.optional) {
      after.push(`if(n<=${o})${obj}[${key}]=null;else{if(n<${o + f.size})fail('bad_length',${o});`,
        ...inner.lines, ...own.map(([k, v]) => `${obj}[${k}]=${v};`), '}');
    } else {
      body.lines.push(...inner.lines);
      entries.push(...own);
    }
    if (f.as_text_when) {
      const w = f.as_text_when;
      after.push(`if(${obj}[${J(w.field)}]===${J(w.value)}){let e=${o};while(e<${o + f.size}&&b[e]!==0)++e;${obj}[${J(`${f.name}_text`)}]=text(b,${o},e);}`);
    }
  }
  entries.push(...tail);
  body.push(`const ${obj}={${entries.map(([k, v]) => `${k}:${v}`).join(',')}};`);
  body.lines.push(...after);
  return obj;
}
function bitsOf(f, v) {
  const parts = f.flag_bits.map((fb) => {
    const raw = `((${v}>>${fb.lo})&${(1 << fb.width) - 1})`;
    const val = fb.width === 1 ? `${raw}!==0` : `flagName(FV${flagValues.push(fb.values) - 1},${raw})`;
    return `${J(fb.name)}:${val}`;
  });
  return `{${parts.join(',')}}`;
}

function lengthsText(m) {
  const runs = m.lengths.map(([a, b]) => (a === b ? `${a}` : `${a}..${b}`));
  const t = runs.length > 1 ? `${runs.slice(0, -1).join(', ')} or ${runs[runs.length - 1]}` : runs[0];
  return `${t} ${m.lengths.length === 1 && m.lengths[0][0] === 1 && m.lengths[0][1] === 1 ? 'byte' : 'bytes'}`;
}
function info(m) {
  const fields = m.fields.map((f) => {
    const ranged = f.valid !== null && f.value !== 'enum';
    const unit = f.unit ? (f.unit.raw_is_physical ? ` ${f.unit.name}` : ' raw') : '';
    return [f.offset, f.offset + f.size, f.name, ranged, ranged ? f.valid.min : 0, ranged ? f.valid.max : 0, unit];
  });
  return `{name:${J(m.name)},lengths:${J(lengthsText(m))},fields:${J(fields)}}`;
}
// A message's decoder: fixed bytes (but those at skip), length, fields.
function decoder(m, id, skip) {
  const body = new Body();
  for (const x of m.fixed) if (!skip.includes(x.offset)) body.push(`if(n>${x.offset}&&b[${x.offset}]!==${x.value})fail(${J(x.error)},${x.offset});`);
  body.push(`if(n<${m.min_size})fail('too_short',n);if(n>${m.max_input})fail('too_long',${m.max_input});`);
  const obj = recordExpr(body, m.fields, 0);
  body.push(`return ${obj};`);
  return `function ${id}(b,dv,n){\n${body.lines.join('\n')}\n}`;
}
// ---- encode: a straight-line encoder per message, with the rules the
// run-time encoder had (runtime.js: rawOf, putText, tailBytes and the error
// helpers, all off the fast path).
let encEnums = [];   // [name -> value] (what a name encodes to), one per enum field
let encValues = [];  // [value -> 1] (the values an enum holds)
const pexpr = (p) => (p.lit !== undefined ? J(p.lit) : p.expr);
const pcat = (p, s) => (p.lit !== undefined ? { lit: p.lit + s } : { expr: `${p.expr}+${J(s)}` });
const pidx = (p, i) => ({ expr: `${p.lit !== undefined ? J(`${p.lit}[`) : `${p.expr}+'['`}+${i}+']'` });
class EncBody {
  constructor(info) { this.lines = []; this.n = 0; this.info = info; this.float = false; }
  tmp(c = 'x') { return `${c}${this.n++}`; }
  push(s) { this.lines.push(s); }
}
function encElement(b, f, v, o, p) {
  const M = b.info;
  if (f.type === 'record') {
    const r = b.tmp('r');
    b.push(`const ${r}=${v}??{};if(typeof ${r}!=='object'||Array.isArray(${r}))notObject(${pexpr(p)});`);
    encRecord(b, f.record.fields, r, o, p, false);
    return;
  }
  if (f.type === 'text') {
    b.push(`if(putText(out,${v},${o},${f.capacity},${pexpr(p)}))bad(E,${M},'value_out_of_range',${o},${pexpr(p)});`);
    return;
  }
  if (f.type === 'tail') return;  // written once the frame exists
  if (f.type === 'f32le') {
    b.float = true;
    b.push(`dv.setFloat32(${o},${v}===undefined?0:${v}===null?NaN:Number(${v}),true);`);
    return;
  }
  const x = b.tmp();
  let en = 'null';
  if (f.enum) en = `EE${encEnums.push(Object.fromEntries(f.enum.map((e) => [e.name, e.value]))) - 1}`;
  // fast path: a number that is a valid value; anything else (not given, a
  // boolean, a name, not an integer, out of range) goes to intSlow
  if (f.enum) {
    const t = `EV${encValues.push(Object.fromEntries(f.enum.map((e) => [e.value, 1]))) - 1}`;
    b.push(`const ${x}=typeof ${v}==='number'&&${t}[${v}]!==undefined?${v}:intSlow(${v},${en},${t},0,0,E,${M},${o},${pexpr(p)});`);
  } else {
    const [lo, hi] = f.valid ? [f.valid.min, f.valid.max] : [-Infinity, Infinity];
    // int32 bounds: an int32 v is in lo..hi when (v-lo)>>>0 <= hi-lo (one compare)
    const test = lo >= -2147483648 && hi <= 2147483647
      ? `(${v}|0)===${v}&&${lo === 0 ? `${v}>>>0` : lo < 0 ? `(${v}+${-lo})>>>0` : `(${v}-${lo})>>>0`}<=${hi - lo}`
      : `Number.isInteger(${v})&&${v}>=${lo}&&${v}<=${hi}`;
    b.push(`const ${x}=typeof ${v}==='number'&&${test}?${v}:intSlow(${v},null,null,${lo},${hi},E,${M},${o},${pexpr(p)});`);
  }
  if (f.type === 'bits') {
    const m = ((1 << f.bits.width) - 1) << f.bits.lo;
    b.push(`out[${o}]=(out[${o}]&${~m & 0xff})|((${x}<<${f.bits.lo})&${m});`);
    return;
  }
  // little-endian by byte (a Uint8Array store keeps the low 8 bits, as the tables' DataView stores did)
  const bytes = f.element_size;
  for (let k = 0; k < bytes; ++k) b.push(`out[${o}${k ? `+${k}` : ''}]=${k ? `${x}>>${8 * k}` : x};`);
}
function encRecord(b, fields, r, base, path, root) {
  const names = fields.map((f) => f.name).join(', ');
  // the field names first: what an object given by hand holds (an if chain: cheaper than a switch or a Set)
  const keys = new Set([...fields.map((f) => f.name),
    ...fields.flatMap((f) => [`${f.name}_bits`, `${f.name}_text`, ...(f.physical ? [f.physical] : [])])]);
  const unknown = `unknownField(${b.info},${root ? "''" : pexpr(path)},k,${J(names)});`;
  b.push(`for(const k in ${r})${keys.size ? `if(${[...keys].map((k) => `k!==${J(k)}`).join('&&')})` : ''}${unknown}`);
  for (const f of fields) {
    const o = base === '0' ? `${f.offset}` : `${base}+${f.offset}`;
    const p = root ? { lit: f.name } : pcat(path, `.${f.name}`);
    const v = b.tmp('v');
    b.push(`const ${v}=${r}[${J(f.name)}];`);
    if (f.optional) b.push(`if(${v}!==undefined&&${v}!==null){`);
    if (f.array) {
      const a = b.tmp('a');
      b.push(`const ${a}=${v}??[];if(!Array.isArray(${a})&&!(${a} instanceof Uint8Array))notArray(${pexpr(p)},${f.count});`);
      b.push(`if(${v}!==undefined&&${a}.length!==${f.count})badCount(${b.info},${pexpr(p)},${a}.length,${f.count},${root});`);
      if (f.count <= 8) {
        for (let i = 0; i < f.count; ++i) {
          const e = b.tmp('e');
          b.push(`const ${e}=${a}[${i}];`);
          encElement(b, f, e, o === `${f.offset}` ? `${f.offset + i * f.element_size}` : `${o}+${i * f.element_size}`, pcat(p, `[${i}]`));
        }
      } else {
        const i = b.tmp('i');
        const e = b.tmp('e');
        b.push(`for(let ${i}=0;${i}<${f.count};++${i}){const ${e}=${a}[${i}];`);
        encElement(b, f, e, `${o}+${i}*${f.element_size}`, pidx(p, i));
        b.push('}');
      }
    } else {
      encElement(b, f, v, o, p);
    }
    if (f.optional) b.push('}');
  }
}
// A message's encoder: its length (optional blocks given, the tail), fixed bytes, fields.
function encoder(m, id, info) {
  const b = new EncBody(info);
  const variable = m.fields.some((f) => f.optional || f.type === 'tail');
  b.push(`${variable ? 'let' : 'const'} size=${m.min_size};`);
  let tail = null;
  for (const f of m.fields) {
    if (f.optional) b.push(`{const v=F[${J(f.name)}];if(v!==undefined&&v!==null)size=Math.max(size,${f.offset + f.size});}`);
    if (f.type === 'tail') {
      tail = f;
      b.push(`const T=tailBytes(F[${J(f.name)}]);if(T.length>${f.capacity})throw messageError(E,${info},'too_long',${f.offset + f.capacity});size=Math.max(size,${f.offset}+T.length);`);
    }
  }
  b.push('const out=new Uint8Array(size);');
  const dvAt = b.lines.length;
  for (const x of m.fixed) {
    if (!variable && x.offset >= m.min_size) continue;
    b.push(variable && x.offset >= m.min_size ? `if(size>${x.offset})out[${x.offset}]=${x.value};` : `out[${x.offset}]=${x.value};`);
  }
  encRecord(b, m.fields, 'F', '0', { lit: '' }, true);
  if (tail) b.push(`out.set(T,${tail.offset});`);
  b.push('return out;');
  if (b.float) b.lines.splice(dvAt, 0, 'const dv=new DataView(out.buffer);');
  return `function ${id}(F){\n${b.lines.join('\n')}\n}`;
}

// lib/schema.js: the schema itself, frozen.
export function schemaModule(schema) {
  return `// Generated by js/gen/generate.js from js/schema.json. Do not edit.\nconst freeze = (o) => { for (const v of Object.values(o)) if (v && typeof v === 'object') freeze(v); return Object.freeze(o); };\nexport default freeze(${J(schema)});\n`;
}

export function generate(schema, p) {
  enumTables = [];
  flagValues = [];
  encEnums = [];
  encValues = [];
  const out = [];
  const keyed = p.key_offsets;
  const decs = p.messages.map((m, i) => decoder(m, `d${i}`, p.frame ? [] : keyed));
  const infos = p.messages.map((m, i) => `const M${i}=${info(m)};`);
  const errors = Object.fromEntries(schema.errors.map((e) => [e.name, e.text]));
  const keyOf = (m) => m.key.join(',');
  const directions = [...new Set(p.messages.map((m) => m.direction))];
  const byDir = {};
  for (const d of directions) {
    const t = {};
    p.messages.forEach((m, i) => { if (m.direction === d && m.key.length) t[keyOf(m)] = i; });
    byDir[d ?? 'any'] = t;
  }
  const keyless = p.messages.findIndex((m) => m.key.length === 0);
  out.push(`// Generated by js/gen/generate.js from js/schema.json (schema_version ${schema.schema_version}): ${p.name}, ${p.summary}. Do not edit.`);
  out.push(`import { RobowireError, Fail, fail, hex, tidy, f32, text, bytesOf, messageError, keyError, plainError, encodeWith, intSlow, notObject, notArray, badCount, unknownField, bad, putText, tailBytes, FrameScanner, FrameReassembler, fragmentPayload } from './runtime.js';`);
  out.push(`const E=${J(errors)};`);
  out.push(`function flagName(values,v){return values[v]??String(v);}`);
  out.push(...infos);
  out.push(...decs);
  out.push(enumTables.map((t, i) => `const EN${i}=${J(t)};`).join('\n'));
  out.push(flagValues.map((t, i) => `const FV${i}=${J(t)};`).join('\n'));
  out.push(`const D=[${p.messages.map((_, i) => `d${i}`).join(',')}];const MI=[${p.messages.map((_, i) => `M${i}`).join(',')}];`);
  out.push(`const NAMES=${J(p.messages.map((m) => m.name))};`);
  out.push(`const KEYS=${J(byDir)};`);
  out.push(`const LEN=${J(p.messages.map((m) => [m.min_size, m.max_input]))};`);
  out.push(`const KO=${J(keyed)};const LAST=${keyed[keyed.length - 1]};`);
  // one key byte: the byte itself indexes KEYS (no string built per frame)
  out.push(keyed.length === 1 ? `function keyAt(b){return b[${keyed[0]}];}` : `function keyAt(b){return KO.map((o)=>b[o]).join(',');}`);
  out.push(`function result(i,fields){return{type:'message',protocol:${J(p.name)},message:NAMES[i],fields};}`);
  out.push(`function run(i,b,dv,n){try{return result(i,D[i](b,dv,n));}catch(e){if(e instanceof Fail)throw messageError(E,MI[i],e.code,e.offset);throw e;}}`);
  if (p.frame) {
    out.push(decoder(p.frame, 'dframe', []));
    out.push(`const MF=${info(p.frame)};`);
    // no message takes every key (OSP): bytes of a length the frame does not take, with a
    // start marker wrong or a key no message has, are no frame: the frame's line, as the tool's
    const frameLength = p.frame.lengths.map(([a, z]) => (a === z ? `n===${a}` : `(n>=${a}&&n<=${z})`)).join('||');
    const noFrame = keyless < 0
      ? `if(!(${frameLength})&&(e.code==='bad_header'||i===undefined))throw messageError(E,MF,e.code,e.offset);\n`
      : '';
    out.push(`function decodeAny(b,dv,n){
try{dframe(b,dv,n);}catch(e){if(!(e instanceof Fail))throw e;
if(n<=LAST)throw messageError(E,MF,e.code,e.offset);
const i=KEYS.any[keyAt(b)]??${keyless < 0 ? 'undefined' : keyless};
${noFrame}if(i===undefined)throw keyError(E,KO.map((o)=>b[o]),e.code,e.offset);
throw messageError(E,MI[i],e.code,e.offset);}
const i=KEYS.any[keyAt(b)]??${keyless < 0 ? 'undefined' : keyless};
if(i===undefined)throw keyError(E,KO.map((o)=>b[o]),'unknown_message',KO[0]);
return run(i,b,dv,n);}`);
  } else {
    out.push(`function decodeAs(d,b,dv,n){if(n<=LAST)throw plainError(E,'too_short',n);const i=KEYS[d][keyAt(b)];if(i===undefined)throw keyError(E,KO.map((o)=>b[o]),'unknown_message',KO[0]);return run(i,b,dv,n);}`);
    if (directions.length > 1) {
      out.push(`function fits(i,n){return i!==undefined&&n>=LEN[i][0]&&n<=LEN[i][1];}
function decodeAny(b,dv,n,direction){
if(direction!==undefined&&!(direction in KEYS))throw new TypeError('decode: direction must be '+Object.keys(KEYS).map((x)=>JSON.stringify(x)).join(' or ')+', not '+JSON.stringify(direction));
if(n===0)return decodeAs(${J(directions[0])},b,dv,n);
if(direction!==undefined)return decodeAs(direction,b,dv,n);
const k=keyAt(b),c=KEYS[${J(directions[0])}][k],t=KEYS[${J(directions[1])}][k];
if(c!==undefined&&t===undefined)return decodeAs(${J(directions[0])},b,dv,n);
if(t!==undefined&&c===undefined)return decodeAs(${J(directions[1])},b,dv,n);
if(c===undefined)return decodeAs(${J(directions[0])},b,dv,n);
const cf=fits(c,n),tf=fits(t,n);
if(cf&&!tf)return decodeAs(${J(directions[0])},b,dv,n);
if(tf&&!cf)return decodeAs(${J(directions[1])},b,dv,n);
if(cf&&tf)throw new RobowireError('0x'+b[0].toString(16).toUpperCase().padStart(2,'0')+' is the ${directions[0]} '+NAMES[c]+' ('+MI[c].lengths+') and the ${directions[1]} '+NAMES[t]+' ('+MI[t].lengths+'); '+n+(n===1?' byte':' bytes')+' given: pass the direction ('+${J(directions.map((d) => `'${d}'`).join(' or '))}+')',{messageName:null});
return decodeAs(${J(directions[0])},b,dv,n);}`);
    } else {
      out.push(`function decodeAny(b,dv,n){return decodeAs('any',b,dv,n);}`);
    }
  }
  out.push(`// decode(bytes, {direction}) -> {type:'message', protocol, message, fields}; RobowireError otherwise.
export function decode(bytes,{direction}={}){const b=bytesOf(bytes);return decodeAny(b,new DataView(b.buffer,b.byteOffset,b.length),b.length,direction);}`);
  out.push(...p.messages.map((m, i) => encoder(m, `e${i}`, `M${i}`)));
  out.push(encEnums.map((t, i) => `const EE${i}=${J(t)};`).join('\n'));
  out.push(encValues.map((t, i) => `const EV${i}=${J(t)};`).join('\n'));
  out.push(`const ENCODERS=[${p.messages.map((_, i) => `e${i}`).join(',')}];const INDEX=new Map(NAMES.map((n,i)=>[n,i]));`);
  out.push(`// encode(message, fields) or encode(decoded) -> Uint8Array; RobowireError for a value it cannot hold.
export function encode(message,fields){
if(typeof message==='string'&&typeof fields==='object'&&fields!==null)switch(message){${p.messages.map((m, i) => `case ${J(m.name)}:return e${i}(fields);`).join('')}}
return encodeWith(${J(p.name)},INDEX,ENCODERS,message,fields);}`);
  if (p.stream === 'scanner') {
    out.push(`// new Scanner(): .push(bytes) -> records of the frames found (as \`robowire scan ${p.name} --json\`); .counters.
export class Scanner extends FrameScanner{constructor(){super(${p.frame.min_size},${J(p.frame.fixed.map((x) => [x.offset, x.value]))},decode,${J(p.name)});}}`);
  }
  if (p.stream === 'reassembler') {
    const field = (n) => p.frame.fields.find((f) => f.name === n);
    const layout = { size: p.frame.min_size, command: field('command').offset, remaining: field('remaining').offset,
      payload: field('payload').offset, payload_size: field('payload').count };
    const jsonCommand = p.messages.find((m) => m.name === p.frame.name).fields.find((f) => f.as_text_when).as_text_when.value;
    out.push(`const LAYOUT=${J(layout)};const FIXED=${J(p.frame.fixed.map((x) => [x.offset, x.value]))};
function frameOnly(b){const n=b.length;try{return dframe(b,new DataView(b.buffer,b.byteOffset,n),n);}catch(e){if(e instanceof Fail)throw messageError(E,MF,e.code,e.offset);throw e;}}
// new Reassembler(): .push(frame) -> records as \`robowire scan ${p.name} --json\` prints a frame's line; .counters.
export class Reassembler extends FrameReassembler{constructor(){super(LAYOUT,decode,frameOnly,${J(p.name)},E);}}
const utf8=new TextEncoder();
// fragment(message, fields): the message's frame, in an array. fragment(bytes or text[, {command}]):
// the frames of a payload (a JSON request by default, command ${jsonCommand}), remaining counting down to 0.
export function fragment(message,fields){
if(typeof message==='string'&&fields!==undefined&&!('command' in fields))return[encode(message,fields)];
const payload=typeof message==='string'?utf8.encode(message):bytesOf(message);
return fragmentPayload(LAYOUT,FIXED,fields?.command??${jsonCommand},payload);}`);
  }
  return `${out.join('\n')}\n`;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const here = new URL('..', import.meta.url).pathname;
  const schema = JSON.parse(readFileSync(process.argv[2] ?? `${here}schema.json`, 'utf8'));
  const dir = process.argv[3] ?? `${here}lib`;
  for (const p of schema.protocols) writeFileSync(`${dir}/${p.name}.js`, generate(schema, p));
  writeFileSync(`${dir}/schema.js`, schemaModule(schema));
}
