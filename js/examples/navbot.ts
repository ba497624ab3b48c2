// NAVBOT-ES02: a JSON command cut into 20-byte frames, and put together again.
import { navbot } from 'robowire';

const frames: Uint8Array[] = navbot.fragment('{"mode":"balance"}', { command: 2 });
const raw: Uint8Array[] = navbot.fragment(new TextEncoder().encode('{"a":1}'));
const maneuver: Uint8Array[] = navbot.fragment('maneuver', { pitch: 10 });
const reassembler = new navbot.Reassembler();
for (const frame of [...frames, ...raw, ...maneuver]) {
  for (const record of reassembler.push(frame)) console.log(record.type);
}
