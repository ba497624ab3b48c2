// Decode what a BuWizz3 sends: its status report, from a Web Bluetooth
// notification's DataView (or any bytes), with the types of index.d.ts.
import { buwizz3, RobowireError, type Buwizz3 } from 'robowire';

export function showStatus(value: DataView): string {
  let m: Buwizz3.Message;
  try {
    m = buwizz3.decode(value, { direction: 'notification' });
  } catch (e) {
    if (e instanceof RobowireError) return `bad frame: ${e.code} at byte ${e.offset}: ${e.message}`;
    throw e;
  }
  if (m.message !== 'status') return m.message;
  const s = m.fields;  // Buwizz3.Status
  const amps = s.motor_current.value.map((a) => a.toFixed(3)).join(' ');
  const pid = s.pid_state === null ? 'no PID block' : `PID output ${s.pid_state.output}`;
  return `${s.battery_voltage.value.toFixed(2)} ${s.battery_voltage.unit}, battery ${s.flags_bits.battery}, ` +
    `${s.temperature_c} degC, motors ${amps} A, ${pid}`;
}

// Is this advertisement a BuWizz3 in application mode?
export function isBrick(advertisement: Uint8Array, scanResponse?: Uint8Array): boolean {
  const a = buwizz3.parseAdvertisement(advertisement, scanResponse);
  return a !== null && a.mode === 'application';
}
