// Helpers of the console that need no browser (tested under Node too).

// Hex in the spellings the command-line tool reads: "01 6D 50", "016d50",
// "0x01,0x6D,0x50", "01-6D-50", "(0x) 01-6D-50", "01:6D:50". Throws an Error
// naming the bad token.
export function parseHex(text) {
  const tokens = text.replace(/\(0x\)/gi, ' ').split(/[\s,:;-]+/).filter((t) => t !== '');
  const out = [];
  for (const t of tokens) {
    const prefixed = /^0x/i.test(t);
    const digits = prefixed ? t.slice(2) : t;
    if (!/^[0-9a-f]+$/i.test(digits)) throw new Error(`bad hex: "${t}" is not hex`);
    if (prefixed && digits.length <= 2) out.push(parseInt(digits, 16));
    else if (digits.length % 2 !== 0) throw new Error(`bad hex: odd number of hex digits in "${t}"`);
    else for (let i = 0; i < digits.length; i += 2) out.push(parseInt(digits.slice(i, i + 2), 16));
  }
  return new Uint8Array(out);
}

export function toHex(bytes) {
  return Array.from(bytes, (b) => b.toString(16).toUpperCase().padStart(2, '0')).join(' ');
}

// BuWizz3 motor power from percent (-100..100): raw = p x 127 / 100, rounded
// half away from zero (50 % -> 64), as docs/buwizz3.md says. Used when the
// package has no buwizz3.powerFromPercent.
export function powerFromPercent(p) {
  if (!(p >= -100 && p <= 100)) throw new RangeError(`power ${p} % is outside -100..100`);
  return Math.sign(p) * Math.floor((Math.abs(p) * 127 + 50) / 100);
}

// BuWizz3 GATT UUIDs (docs/buwizz3.md), used when the package has no buwizz3.uuids.
export const buwizz3Uuids = {
  service: '500592d1-74fb-4481-88b3-9919b1676e93',
  application: '50052901-74fb-4481-88b3-9919b1676e93',
};
// NAVBOT-ES02 (docs/navbot.md): commands are written to `write`, the robot answers on `notify`.
export const navbotUuids = {
  service: '6e400011-b5a3-f393-e0a9-e50e24dcca9e',
  write: '6e400012-b5a3-f393-e0a9-e50e24dcca9e',
  notify: '6e400013-b5a3-f393-e0a9-e50e24dcca9e',
};
export const ospBaudRate = 115200;

// One log entry as the saved file has it: a `#` comment line with the time,
// the direction and the decoded JSON (or the error), then the frame as a hex
// line. `robowire decode <protocol> --file` skips the comments and decodes
// the hex lines.
export function logLines({ time, direction, bytes, decoded, error }) {
  const what = error ? `error: ${error}` : JSON.stringify(decoded);
  return `# ${time} ${direction} ${what}\n${toHex(bytes)}\n`;
}
