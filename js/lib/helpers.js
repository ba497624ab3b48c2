// BuWizz3 helpers: motor power from percent and back, the GATT UUIDs and the
// advertisement parser, computed as the C++ library computes them
// (include/robowire/buwizz3/units.hpp, uuids.hpp, advertisement.hpp).
// docs/javascript.md, "BuWizz3 helpers".
import { RobowireError } from './runtime.js';

function finiteNumber(fn, what, v) {
  if (typeof v !== 'number') throw new TypeError(`${fn}: ${what} must be a number, got ${v === null ? 'null' : typeof v}`);
  return v;
}

// 0x30 / 0x31 motor power: the raw value -127..127 for `percent` -100..100
// (positive is forwards): percent x 127 / 100 rounded half away from zero
// (50 -> 64, -50 -> -64, 1 -> 1, 100 -> 127). Outside -100..100 or NaN: RangeError.
export function powerFromPercent(percent) {
  finiteNumber('powerFromPercent', 'percent', percent);
  if (!(percent >= -100 && percent <= 100)) {
    throw new RangeError(`powerFromPercent: percent must be within -100..100, got ${percent}`);
  }
  const raw = (percent * 127) / 100;  // the C++ double arithmetic, in the same order
  return Math.trunc(raw < 0 ? raw - 0.5 : raw + 0.5) | 0;  // | 0: no -0
}

// The inverse: percent of full power for a raw power -128..127 (an integer):
// raw x 100 / 127 (127 -> 100, 64 -> 50.39..., -127 -> -100). Other values: RangeError.
export function percentFromPower(raw) {
  finiteNumber('percentFromPower', 'raw', raw);
  if (!Number.isInteger(raw) || raw < -128 || raw > 127) {
    throw new RangeError(`percentFromPower: raw must be an integer within -128..127, got ${raw}`);
  }
  return (raw * 100) / 127;
}

// The GATT UUIDs (canonical lower-case strings, as Web Bluetooth takes them).
// `direction`: 'both' = commands written to it, replies and reports notified.
const base = (short) => `5005${short}-74fb-4481-88b3-9919b1676e93`;
const characteristic = (short, what) => Object.freeze({ uuid: base(short), direction: 'both', what });
export const uuids = Object.freeze({
  service: base('92d1'),
  application: characteristic('2901', 'commands (write) and the status report (notify)'),
  bootloader: characteristic('8000', 'firmware update (write and notify)'),
  // UART on motor ports 1-4: uart[0] is port 1.
  uart: Object.freeze([1, 2, 3, 4].map((n) => characteristic(`390${n}`, `UART on motor port ${n} (write and notify)`))),
});

function bytesOf(fn, what, b) {
  if (b instanceof Uint8Array) return b;
  if (b instanceof ArrayBuffer) return new Uint8Array(b);
  if (ArrayBuffer.isView(b)) return new Uint8Array(b.buffer, b.byteOffset, b.byteLength);
  throw new TypeError(`${fn}: ${what} must be a Uint8Array, ArrayBuffer or DataView`);
}

const AD_MANUFACTURER_DATA = 0xff;
const AD_UUID128_INCOMPLETE = 0x06;
const AD_UUID128_COMPLETE = 0x07;
const AD_NAME_SHORTENED = 0x08;
const AD_NAME_COMPLETE = 0x09;
const serviceOnAir = Uint8Array.from(uuids.service.replaceAll('-', '').match(/../g).map((h) => parseInt(h, 16))).reverse();
const names = new TextDecoder('utf-8');  // not fatal: a byte that is no UTF-8 becomes U+FFFD

// Walks the AD structures (length, type, data) into `out`; returns the offset
// of a length byte that runs past the end, or -1. A zero length ends the data.
function readStructures(adv, out) {
  let pos = 0;
  while (pos < adv.length) {
    const len = adv[pos];
    if (len === 0) return -1;
    if (len > adv.length - pos - 1) return pos;
    const type = adv[pos + 1];
    const d = adv.subarray(pos + 2, pos + 1 + len);
    pos += 1 + len;
    if (type === AD_MANUFACTURER_DATA && d.length >= 8 && d[0] === 0x4e && d[1] === 0x05 && d[2] === 0x42 && d[3] === 0x57) {
      out.has_manufacturer_data = true;
      if (d[4] === 0x42 && d[5] === 0x4c) {  // 'B' 'L'
        out.mode = 'bootloader';
        out.firmware_version = [0, 0];
      } else {
        out.mode = 'application';
        out.firmware_version = [d[4], d[5]];
      }
      out.serial_low16 = d[6] | (d[7] << 8);
    } else if (type === AD_UUID128_INCOMPLETE || type === AD_UUID128_COMPLETE) {
      for (let i = 0; i + 16 <= d.length; i += 16) {
        if (serviceOnAir.every((x, k) => d[i + k] === x)) out.has_service_uuid = true;
      }
    } else if (type === AD_NAME_COMPLETE || type === AD_NAME_SHORTENED) {
      out.local_name = names.decode(d.subarray(0, 29));  // the C++ keeps the first 29 bytes
    }
  }
  return -1;
}

// A BuWizz3's advertising data (and optionally its scan response), raw AD
// structures as on air: { mode: 'application' | 'bootloader' | 'unknown',
// firmware_version: [x, y] (3.22 advertises [3, 0x22]), serial_low16,
// has_manufacturer_data, has_service_uuid, local_name (string or null) },
// or null when neither the manufacturer data 4E 05 42 57 nor the service UUID
// is there. The last manufacturer data and name count. A length byte that
// runs past the end: RobowireError bad_length at that byte (scan response
// offsets count after the advertisement).
export function parseAdvertisement(advertisement, scanResponse) {
  const adv = bytesOf('parseAdvertisement', 'advertisement', advertisement);
  const scan = scanResponse === undefined || scanResponse === null
    ? new Uint8Array(0) : bytesOf('parseAdvertisement', 'scanResponse', scanResponse);
  const out = {
    mode: 'unknown', firmware_version: [0, 0], serial_low16: 0,
    has_manufacturer_data: false, has_service_uuid: false, local_name: null,
  };
  const bad = readStructures(adv, out);
  const bad2 = readStructures(scan, out);
  const offset = bad >= 0 ? bad : bad2 >= 0 ? adv.length + bad2 : -1;
  if (offset >= 0) {
    throw new RobowireError(`advertisement: length matches no form of the message at byte ${offset}`,
      { code: 'bad_length', offset });
  }
  return out.has_manufacturer_data || out.has_service_uuid ? out : null;
}
