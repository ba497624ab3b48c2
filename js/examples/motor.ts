// Drive BuWizz3 motors: set_motor_data from percentages, written to the
// application characteristic.
import { buwizz3 } from 'robowire';

// The part of a Web Bluetooth characteristic used here.
interface Writable {
  writeValueWithoutResponse(value: Uint8Array): Promise<void>;
}

export const characteristicUuid: string = buwizz3.uuids.application.uuid;

// Ports 1-6 in percent (-100..100); brake the ports at 0 %.
export async function drive(c: Writable, percent: [number, number, number, number, number, number]): Promise<void> {
  const power = percent.map((p) => buwizz3.powerFromPercent(p)) as [number, number, number, number, number, number];
  const brake_flags = power.reduce((bits, p, i) => (p === 0 ? bits | (1 << i) : bits), 0);
  await c.writeValueWithoutResponse(buwizz3.encode('set_motor_data', { power, brake_flags }));
}

export const stop = (c: Writable) => c.writeValueWithoutResponse(buwizz3.encode('set_motor_data', {}));
