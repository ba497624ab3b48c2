// Runs in the page (page.addInitScript) before the console loads: a fake
// BuWizz3 / NAVBOT-ES02 behind navigator.bluetooth and a fake OSP port
// behind navigator.serial. The test plays the device's side through
// window.fake: notify(hex) sends a notification, serialData(hex) a chunk of
// the serial stream; window.fake.writes records every write with its time.
export function installFakeDevices() {
  const bytesOf = (hex) => new Uint8Array(hex.match(/[0-9a-f]{2}/gi).map((h) => parseInt(h, 16)));
  const hexOf = (b) => Array.from(b, (x) => x.toString(16).toUpperCase().padStart(2, '0')).join(' ');
  const fake = { writes: [], requests: [], listeners: [], connected: false, serialOptions: null, serialController: null };
  window.fake = fake;
  class Characteristic extends EventTarget {
    constructor(uuid) {
      super();
      this.uuid = uuid;
      this.properties = { write: true, writeWithoutResponse: true, notify: true };
      this.value = null;
    }
    async startNotifications() { fake.notifying = true; return this; }
    async writeValueWithoutResponse(data) { fake.writes.push({ t: performance.now(), uuid: this.uuid, hex: hexOf(new Uint8Array(data.buffer ?? data, data.byteOffset ?? 0, data.byteLength)) }); }
    async writeValueWithResponse(data) { return this.writeValueWithoutResponse(data); }
    async writeValue(data) { return this.writeValueWithoutResponse(data); }
  }
  const characteristics = new Map();
  const characteristic = (uuid) => {
    if (!characteristics.has(uuid)) characteristics.set(uuid, new Characteristic(uuid));
    return characteristics.get(uuid);
  };
  fake.notify = (hex, uuid) => {
    const c = uuid ? characteristic(uuid) : [...characteristics.values()].find((x) => x.uuid !== fake.writeOnly);
    const b = bytesOf(hex);
    c.value = new DataView(b.buffer);
    c.dispatchEvent(new Event('characteristicvaluechanged'));
  };
  const device = Object.assign(new EventTarget(), {
    id: 'fake', name: 'Fake device',
    gatt: {
      get connected() { return fake.connected; },
      async connect() {
        fake.connected = true;
        return { async getPrimaryService(s) { fake.service = s; return { async getCharacteristic(c) { return characteristic(c); } }; } };
      },
      disconnect() { fake.connected = false; },
    },
  });
  Object.defineProperty(navigator, 'bluetooth', {
    value: { async requestDevice(options) { fake.requests.push(options); return device; } },
  });
  Object.defineProperty(navigator, 'serial', {
    value: {
      async requestPort() {
        return {
          async open(options) { fake.serialOptions = options; },
          readable: new ReadableStream({ start(controller) { fake.serialController = controller; } }),
          async close() {},
        };
      },
    },
  });
  fake.serialData = (hex) => fake.serialController.enqueue(bytesOf(hex));
}
