// The other route, for bench.js: JavaScript generated from the tables
// (`robowire list --json buwizz3`, tools/lib/schema.hpp) -- a straight-line
// DataView decoder and encoder per message, compiled with new Function.
// Covers the field kinds of the messages benchmarked (integers, f32, arrays,
// records, an optional block, units, flag bits); text, tails, enums, bools
// and bit fields are not generated. A prototype to measure, not shipped.
const getter = {
  u8: (o) => `b[${o}]`, i8: (o) => `dv.getInt8(${o})`,
  u16le: (o) => `dv.getUint16(${o},true)`, i16le: (o) => `dv.getInt16(${o},true)`,
  u32le: (o) => `dv.getUint32(${o},true)`, i32le: (o) => `dv.getInt32(${o},true)`,
  f32le: (o) => `f32(dv,${o})`,
};
const setter = {
  u8: 'setUint8', i8: 'setInt8', u16le: 'setUint16', i16le: 'setInt16',
  u32le: 'setUint32', i32le: 'setInt32', f32le: 'setFloat32',
};
function physicalKey(name) {
  return name.endsWith('_raw') ? name.slice(0, -4) : `${name}_physical`;
}
function unsupported(f) {
  if (!(f.type in getter) && f.type !== 'record') throw new Error(`generate: ${f.name}: ${f.type} not generated`);
  if (f.enum || f.value === 'bool') throw new Error(`generate: ${f.name}: ${f.value} not generated`);
}

// An expression of the decoded fields object of `fields` based at `base`.
function decodeFields(fields, base) {
  const parts = [];
  for (const f of fields) {
    unsupported(f);
    const at = (i) => base + f.offset + i * f.element_size;
    const one = (i) => (f.type === 'record' ? decodeFields(f.record.fields, at(i)) : getter[f.type](at(i)));
    let v = f.array ? `[${Array.from({ length: f.count }, (_, i) => one(i)).join(',')}]` : one(0);
    if (f.optional) v = `(n>=${base + f.offset + f.size}?${v}:null)`;
    parts.push(`${JSON.stringify(f.name)}:${v}`);
    if (f.unit) {
      const exact = f.unit.scale === 1 && f.unit.offset === 0;
      const phys = (i) => (exact ? getter[f.type](at(i)) : `tidy(${getter[f.type](at(i))}*${f.unit.scale}+${f.unit.offset})`);
      const value = f.array ? `[${Array.from({ length: f.count }, (_, i) => phys(i)).join(',')}]` : phys(0);
      parts.push(`${JSON.stringify(physicalKey(f.name))}:{value:${value},unit:${JSON.stringify(f.unit.name)}}`);
    }
    if (f.flag_bits) {
      const bits = f.flag_bits.map((fb) => {
        const raw = `((${getter[f.type](at(0))}>>${fb.lo})&${(1 << fb.width) - 1})`;
        const val = fb.width === 1 ? `${raw}!==0` : `${JSON.stringify(fb.values)}[${raw}]`;
        return `${JSON.stringify(fb.name)}:${val}`;
      });
      parts.push(`${JSON.stringify(`${f.name}_bits`)}:{${bits.join(',')}}`);
    }
  }
  return `{${parts.join(',')}}`;
}

export function generateDecoder(m) {
  const key = m.fixed.map((x) => `if(n>${x.offset}&&b[${x.offset}]!==${x.value})throw err(${JSON.stringify(x.error)},${x.offset});`).join('');
  const runs = m.lengths.map(([lo, hi]) => `(n>=${lo}&&n<=${hi})`).join('||');
  const body = `const n=b.length;if(n<1)throw err('too_short',0);${key}` +
    `if(n<${m.min_size})throw err('too_short',n);if(n>${m.max_input})throw err('too_long',${m.max_input});` +
    `if(!(${runs}))throw err('bad_length',${m.min_size});` +
    `const dv=new DataView(b.buffer,b.byteOffset,n);` +
    `return{type:'message',protocol:'buwizz3',message:${JSON.stringify(m.name)},fields:${decodeFields(m.fields, 0)}};`;
  return new Function('tidy', 'f32', 'err', `return function decode_${m.name}(b){${body}}`)(
    (v) => Number(v.toPrecision(15)),
    (dv, o) => { const v = dv.getFloat32(o, true); return Number.isFinite(v) ? v : null; },
    (code, offset) => Object.assign(new Error(`${code} at byte ${offset}`), { code, offset }));
}

export function generateEncoder(m) {
  let body = `const out=new Uint8Array(${m.min_size});`;
  if (m.fields.some((f) => f.element_size > 1)) body += 'const dv=new DataView(out.buffer);';
  body += m.fixed.map((x) => `out[${x.offset}]=${x.value};`).join('');
  for (const f of m.fields) {
    unsupported(f);
    if (f.type === 'record' || f.optional) throw new Error(`generate: ${f.name}: records not generated for encode`);
    const check = (v, o) => (f.valid
      ? `if(!Number.isInteger(${v})||${v}<${f.valid.min}||${v}>${f.valid.max})throw err('value_out_of_range',${o});` : '');
    const put = (v, o) => `${check(v, o)}` +
      (f.element_size === 1 ? `out[${o}]=${v}&255;` : `dv.${setter[f.type]}(${o},${v},true);`);
    const name = JSON.stringify(f.name);
    if (f.array) {
      body += `{const a=fields[${name}]??${JSON.stringify(new Array(f.count).fill(0))};if(a.length!==${f.count})throw err('bad_length',${f.offset});`;
      for (let i = 0; i < f.count; ++i) body += put(`a[${i}]`, f.offset + i * f.element_size);
      body += '}';
    } else {
      body += `{const v=fields[${name}]??0;${put('v', f.offset)}}`;
    }
  }
  body += 'return out;';
  return new Function('err', `return function encode_${m.name}(fields){${body}}`)(
    (code, offset) => Object.assign(new Error(`${code} at byte ${offset}`), { code, offset }));
}
