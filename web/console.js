// The robowire web console: Web Bluetooth (BuWizz3, NAVBOT-ES02) and Web
// Serial (OSP), frames decoded by the robowire package. docs/javascript.md.
import * as rw from '../js/index.js';
import { LineChart } from './chart.js';
import * as util from './util.js';

const $ = (id) => document.getElementById(id);
const bw = rw.buwizz3;
// The package's UUID strings when it has them, else those of docs/buwizz3.md.
const strings = (o) => Object.fromEntries(Object.entries(o ?? {}).filter(([, v]) => typeof v === 'string'));
const uuids = { ...util.buwizz3Uuids, ...strings(bw.uuids) };
const powerFromPercent = bw.powerFromPercent ?? util.powerFromPercent;
const DATA_PERIOD_MS = 50;     // status every 50 ms (0x32, 20..255 ms)
const WATCHDOG_S = 2;          // the brick drops the link and stops the motors after 2 s without 0x35
const KEEPALIVE_MS = 1000;     // 0x35 resent every second: each one restarts the watchdog

const log = [];   // { time, direction, bytes, decoded, error }
let session = null;

// ---- log pane --------------------------------------------------------------
function addLog(entry) {
  entry.time = new Date().toISOString();
  log.push(entry);
  const row = document.createElement('div');
  row.className = entry.error ? 'error' : entry.direction;
  const what = entry.error ? `error: ${entry.error}` : JSON.stringify(entry.decoded);
  row.textContent = `${entry.time.slice(11, 23)} ${entry.direction === 'command' ? '>' : '<'} ${util.toHex(entry.bytes)}\n  ${what}`;
  const pane = $('log');
  const atEnd = pane.scrollTop + pane.clientHeight >= pane.scrollHeight - 4;
  pane.append(row);
  while (pane.childElementCount > 500) pane.firstElementChild.remove();
  if (atEnd) pane.scrollTop = pane.scrollHeight;
  $('log-count').textContent = String(log.length);
  $('error-count').textContent = String(log.filter((e) => e.error).length);
}

function saveLog() {
  const text = `# robowire web console log: ${$('protocol').value}, hex lines, read with robowire decode --file\n` +
    log.map(util.logLines).join('');
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([text], { type: 'text/plain' }));
  a.download = `robowire-${$('protocol').value}-${new Date().toISOString().replace(/[:.]/g, '-')}.txt`;
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 10000);
}

// Decodes one frame into a log entry; a bad frame is logged as an error and the stream goes on.
function decodeEntry(codec, bytes, direction) {
  try {
    return { direction, bytes, decoded: codec.decode(bytes, { direction }) };
  } catch (e) {
    return { direction, bytes, error: e.message };
  }
}

// ---- BuWizz3 -----------------------------------------------------------------
const currentChart = new LineChart($('chart-current'), {
  series: ['#1f77b4', '#ff7f0e', '#2ca02c', '#d62728', '#9467bd', '#8c564b'].map((color, i) => ({ label: `${i + 1}`, color })),
  minSpan: 0.5,
});
const accelChart = new LineChart($('chart-accel'), {
  series: [{ label: 'x', color: '#d62728' }, { label: 'y', color: '#2ca02c' }, { label: 'z', color: '#1f77b4' }],
  minSpan: 2,
});

function showStatus(fields) {
  // physical values as the package gives them: { value, unit } (V, A, mg)
  const volts = fields.battery_voltage.value;
  $('battery').textContent = `${volts.toFixed(2)} V`;
  $('temperature').textContent = `${fields.temperature_c} °C`;
  const amps = fields.motor_current.value;
  amps.forEach((a, i) => { $(`current-${i + 1}`).textContent = `${a.toFixed(3)} A`; });
  const g = fields.accel.value.map((mg) => mg / 1000);
  ['x', 'y', 'z'].forEach((axis, i) => { $(`accel-${axis}`).textContent = `${g[i].toFixed(3)} g`; });
  currentChart.push(amps);
  accelChart.push(g);
}

function buildSliders() {
  for (let port = 1; port <= 6; port++) {
    const label = document.createElement('label');
    label.innerHTML = `port ${port} <input type="range" id="power-${port}" min="-100" max="100" step="1" value="0"> <output id="power-${port}-out">0 %</output>`;
    $('sliders').append(label);
    label.querySelector('input').addEventListener('input', (e) => {
      $(`power-${port}-out`).textContent = `${e.target.value} %`;
      session?.sendPower?.();
    });
  }
  $('stop').addEventListener('click', () => {
    for (let port = 1; port <= 6; port++) { $(`power-${port}`).value = '0'; $(`power-${port}-out`).textContent = '0 %'; }
    session?.sendPower?.();
  });
}

// Writes one after the other: a GATT characteristic takes one operation at a time.
function writer(characteristic, codec) {
  let chain = Promise.resolve();
  return (message, fields) => {
    let bytes;
    try {
      bytes = codec.encode(message, fields);
    } catch (e) {
      addLog({ direction: 'command', bytes: new Uint8Array(), error: e.message });
      return chain;
    }
    chain = chain.then(async () => {
      if (characteristic.properties?.writeWithoutResponse && characteristic.writeValueWithoutResponse)
        await characteristic.writeValueWithoutResponse(bytes);
      else if (characteristic.writeValueWithResponse) await characteristic.writeValueWithResponse(bytes);
      else await characteristic.writeValue(bytes);
      addLog(decodeEntry(codec, bytes, 'command'));
    }).catch((e) => setState(`write failed: ${e.message}`));
    return chain;
  };
}

async function connectBuwizz3() {
  const device = await navigator.bluetooth.requestDevice({
    filters: [{ services: [uuids.service] }, { namePrefix: 'BuWizz' }],
    optionalServices: [uuids.service],
  });
  const server = await device.gatt.connect();
  const service = await server.getPrimaryService(uuids.service);
  const ch = await service.getCharacteristic(uuids.application);
  const write = writer(ch, bw);
  ch.addEventListener('characteristicvaluechanged', (event) => {
    const v = event.target.value;
    const bytes = new Uint8Array(v.buffer.slice(v.byteOffset, v.byteOffset + v.byteLength));
    const entry = decodeEntry(bw, bytes, 'notification');
    addLog(entry);
    if (entry.decoded?.message === 'status') showStatus(entry.decoded.fields);
  });
  await ch.startNotifications();
  await write('set_data_period', { period_ms: DATA_PERIOD_MS });
  await write('set_motor_timeout', { mode: 1 });          // coast when the watchdog fires
  await write('activate_watchdog', { timeout_s: WATCHDOG_S });
  const keepalive = setInterval(() => write('activate_watchdog', { timeout_s: WATCHDOG_S }), KEEPALIVE_MS);
  let pending = false;
  const sendPower = () => {   // at most one motor write waiting; it takes the sliders' latest values
    if (pending) return;
    pending = true;
    queueMicrotask(() => {
      pending = false;
      const power = [1, 2, 3, 4, 5, 6].map((p) => powerFromPercent(Number($(`power-${p}`).value)));
      write('set_motor_data', { power });
    });
  };
  return {
    device,
    sendPower,
    async close() {
      clearInterval(keepalive);
      if (device.gatt.connected) {
        await write('set_motor_data', { power: [0, 0, 0, 0, 0, 0] }).catch(() => {});
        device.gatt.disconnect();
      }
    },
  };
}

// ---- NAVBOT-ES02 ---------------------------------------------------------------
async function connectNavbot() {
  const nb = rw.navbot;
  const u = { ...util.navbotUuids, ...strings(nb.uuids) };
  const device = await navigator.bluetooth.requestDevice({ filters: [{ services: [u.service] }], optionalServices: [u.service] });
  const server = await device.gatt.connect();
  const service = await server.getPrimaryService(u.service);
  const notify = await service.getCharacteristic(u.notify);
  const reassembler = nb.Reassembler ? new nb.Reassembler() : null;
  notify.addEventListener('characteristicvaluechanged', (event) => {
    const v = event.target.value;
    const bytes = new Uint8Array(v.buffer.slice(v.byteOffset, v.byteOffset + v.byteLength));
    if (!reassembler) return addLog(decodeEntry(nb, bytes, 'notification'));
    for (const r of reassembler.push(bytes)) addLog(recordEntry(r, bytes, 'notification'));
  });
  await notify.startNotifications();
  return { device, async close() { if (device.gatt.connected) device.gatt.disconnect(); } };
}

// A record of a Scanner or Reassembler as a log entry.
function recordEntry(r, chunk, direction) {
  const hex = r.hex ?? r.frame ?? r.bytes;
  const bytes = hex instanceof Uint8Array ? hex : typeof hex === 'string' ? util.parseHex(hex) : chunk;
  return r.type === 'error' ? { direction, bytes, error: r.error ?? r.message ?? JSON.stringify(r) } : { direction, bytes, decoded: r };
}

// ---- OSP -------------------------------------------------------------------------
async function connectOsp() {
  const port = await navigator.serial.requestPort();
  await port.open({ baudRate: util.ospBaudRate });
  const scanner = new rw.osp.Scanner();
  const reader = port.readable.getReader();
  let open = true;
  (async () => {
    try {
      while (open) {
        const { value, done } = await reader.read();
        if (done) break;
        // a message record carries no bytes (as the tool's scan): its frame is the message encoded again
        for (const r of scanner.push(value)) addLog(recordEntry(r, r.type === 'message' ? rw.osp.encode(r) : value, 'notification'));
      }
    } catch (e) {
      setState(`serial port: ${e.message}`);
    }
  })();
  return {
    async close() {
      open = false;
      await reader.cancel().catch(() => {});
      reader.releaseLock();
      await port.close().catch(() => {});
    },
  };
}

// ---- page ------------------------------------------------------------------------
function setState(text) { $('state').textContent = text; }

function missing(protocol) {
  if (protocol === 'buwizz3') return navigator.bluetooth ? null : 'Web Bluetooth is not available: use Chrome or Edge, on https or localhost.';
  if (protocol === 'navbot') {
    if (!rw.navbot) return 'NAVBOT-ES02: not in this package build.';
    return navigator.bluetooth ? null : 'Web Bluetooth is not available: use Chrome or Edge, on https or localhost.';
  }
  if (!rw.osp) return 'OSP: not in this package build.';
  return navigator.serial ? null : 'Web Serial is not available: use Chrome or Edge, on https or localhost.';
}

function selectProtocol() {
  const p = $('protocol').value;
  for (const name of ['buwizz3', 'navbot', 'osp']) $(`${name}-pane`).hidden = name !== p;
  const why = missing(p);
  $('support').textContent = why ?? '';
  const note = document.querySelector(`#${p}-pane .pane-note`);
  if (note) note.textContent = why ?? '';
  $('connect').disabled = why !== null || session !== null;
}

async function connect() {
  const p = $('protocol').value;
  $('connect').disabled = true;
  $('protocol').disabled = true;
  setState('connecting...');
  try {
    session = await { buwizz3: connectBuwizz3, navbot: connectNavbot, osp: connectOsp }[p]();
    session.device?.addEventListener?.('gattserverdisconnected', () => disconnect('disconnected by the device'));
    setState(`connected${session.device?.name ? `: ${session.device.name}` : ''}`);
    $('disconnect').disabled = false;
  } catch (e) {
    session = null;
    setState(`not connected: ${e.message}`);
    $('protocol').disabled = false;
    selectProtocol();
  }
}

async function disconnect(why = 'not connected') {
  const s = session;
  session = null;
  if (s) await s.close().catch(() => {});
  setState(why);
  $('disconnect').disabled = true;
  $('protocol').disabled = false;
  selectProtocol();
}

function decodePasted() {
  const out = $('hex-output');
  const p = $('hex-protocol').value;
  const codec = rw[p];
  out.className = '';
  if (!codec?.decode) {
    out.className = 'error';
    out.textContent = `${p}: not in this package build`;
    return;
  }
  try {
    const bytes = util.parseHex($('hex-input').value);
    const direction = $('hex-direction').value || undefined;
    out.textContent = JSON.stringify(codec.decode(bytes, { direction }), null, 2);
  } catch (e) {
    out.className = 'error';
    out.textContent = `error: ${e.message}`;
  }
}

buildSliders();
$('protocol').addEventListener('change', selectProtocol);
$('connect').addEventListener('click', connect);
$('disconnect').addEventListener('click', () => disconnect());
$('save-log').addEventListener('click', saveLog);
$('clear-log').addEventListener('click', () => { log.length = 0; $('log').replaceChildren(); $('log-count').textContent = '0'; $('error-count').textContent = '0'; });
$('hex-decode').addEventListener('click', decodePasted);
selectProtocol();
document.body.dataset.ready = 'true';
