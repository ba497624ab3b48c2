// robowire for JavaScript: BuWizz3, NAVBOT-ES02 and OSP messages decoded to
// the command-line tool's JSON and encoded from plain objects, by JavaScript
// generated from the library's tables (schema.json, gen/generate.js).
// docs/javascript.md.
import * as buwizz3Codec from './lib/buwizz3.js';
import * as navbotCodec from './lib/navbot.js';
import * as ospCodec from './lib/osp.js';
import { parseAdvertisement, percentFromPower, powerFromPercent, uuids } from './lib/helpers.js';
import { RobowireError } from './lib/runtime.js';
import schemaDocument from './lib/schema.js';

export { RobowireError };
// The tables the codecs were generated from (`robowire list --json`, docs/cli.md).
export const schema = schemaDocument;
// BuWizz3: decode(bytes, {direction}) -> {type, protocol, message, fields};
// encode(message, fields) -> Uint8Array. direction: "command" (host to
// device), "notification" (device to host) or absent (the command byte decides).
// Helpers: powerFromPercent(p) -> raw power, percentFromPower(raw) -> %,
// uuids (service, characteristics), parseAdvertisement(adv, scanResponse).
export const buwizz3 = Object.freeze({
  decode: buwizz3Codec.decode,
  encode: buwizz3Codec.encode,
  powerFromPercent,
  percentFromPower,
  uuids,
  parseAdvertisement,
});
// NAVBOT-ES02: one 20-byte frame at a time.
export const navbot = Object.freeze({
  decode: navbotCodec.decode,
  encode: navbotCodec.encode,
  Reassembler: navbotCodec.Reassembler,  // new Reassembler().push(frame) -> records, .counters
  fragment: navbotCodec.fragment,  // fragment(message, fields) or fragment(bytes or text) -> 20-byte frames
});
// OSP: one 10-byte frame at a time; new Scanner().push(bytes) -> records, .counters.
export const osp = Object.freeze({ decode: ospCodec.decode, encode: ospCodec.encode, Scanner: ospCodec.Scanner });
