// The page of `locus view`: asks the server for frames while the user turns, zooms and edits the
// surface. Progressive: while the pointer moves, frames at a quarter of the resolution; when it
// rests, a half and then the full one. A newer request aborts the one in flight (and the server
// cancels its render: the same `client`).
"use strict";

const SIDE = 512;
const LEVELS = [SIDE / 4, SIDE / 2, SIDE];
const client = Math.random().toString(36).slice(2);
const $ = (id) => document.getElementById(id);

const state = window.locusState = {
  source: "equation",      // or "startup": the scene the command line named
  equation: "",
  parameters: [],          // [{name, min, max, value}]
  camera: null,            // {eye, target, up, fov}; null: the server frames the surface
  method: "default",
  frames: 0,
};
let inFlight = null;        // AbortController of the frame being fetched
let pending = null;         // the level asked for while one was in flight
let refineTimer = 0;
let animating = null;
let frameUrl = null;

const sub = (a, b) => a.map((v, i) => v - b[i]);
const add = (a, b) => a.map((v, i) => v + b[i]);
const scale = (a, s) => a.map((v) => v * s);
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const norm = (a) => scale(a, 1 / Math.hypot(...a));

// Rotates v about the unit axis k by angle t (Rodrigues).
function rotate(v, k, t) {
  const c = Math.cos(t), s = Math.sin(t);
  return add(add(scale(v, c), scale(cross(k, v), s)), scale(k, dot(k, v) * (1 - c)));
}

function hexToLinear(hex) {
  const n = parseInt(hex.slice(1), 16);
  return [(n >> 16) & 255, (n >> 8) & 255, n & 255]
    .map((c) => Math.pow(c / 255, 2.2).toFixed(4)).join(",");
}

function paramText() {
  return state.parameters.map((p) => `${p.name}=${Number(p.value)}`).join(";");
}

function cameraText() {
  const c = state.camera;
  if (!c) return "auto";
  return [...c.eye, ...c.target, ...c.up, c.fov].map((v) => Number(v).toPrecision(12)).join(",");
}

function form(side, extra) {
  const f = new URLSearchParams({
    client, source: state.source, equation: state.equation, params: paramText(),
    width: side, height: side, camera: cameraText(), method: state.method,
    front: hexToLinear($("front").value), back: hexToLinear($("back").value),
    light: `${$("azimuth").value},${$("elevation").value}`,
    shadows: $("shadows").checked ? "1" : "0",
  });
  for (const [k, v] of Object.entries(extra || {})) f.set(k, v);
  return f;
}

function showError(message, column) {
  const box = $("error");
  if (!message) { box.hidden = true; box.textContent = ""; return; }
  box.hidden = false;
  let text = message;
  if (column) {
    const line = state.equation.split("\n")[0];
    text += "\n" + line + "\n" + " ".repeat(Math.max(0, column - 1)) + "^";
  }
  box.textContent = text;
}

async function requestFrame(level) {
  if (inFlight) {
    if (level === 0) { pending = 0; return; }   // while dragging: the next one, not a queue
    inFlight.abort();
  }
  // This frame shows the latest state: a preview queued behind the one just aborted is stale
  // (run after this frame, it became the last one shown, and the refinement never asked for
  // the full frame).
  pending = null;
  const controller = new AbortController();
  inFlight = controller;
  const side = LEVELS[level];
  const started = performance.now();
  try {
    const response = await fetch("/api/render", { method: "POST", body: form(side), signal: controller.signal });
    if (!response.ok) {
      const error = await response.json().catch(() => ({ error: response.statusText }));
      if (response.status !== 409) showError(error.error, error.field === "equation" ? error.column : 0);
      return;
    }
    showError("");
    const blob = await response.blob();
    if (frameUrl) URL.revokeObjectURL(frameUrl);
    frameUrl = URL.createObjectURL(blob);
    await new Promise((resolve) => { $("view").onload = resolve; $("view").src = frameUrl; });
    $("save").href = frameUrl;
    const camera = response.headers.get("X-Locus-Camera").split(",").map(Number);
    if (!state.camera) {
      state.camera = { eye: camera.slice(0, 3), target: camera.slice(3, 6), up: camera.slice(6, 9), fov: camera[9] };
    }
    const seconds = Number(response.headers.get("X-Locus-Seconds"));
    const undecided = response.headers.get("X-Locus-Undecided");
    $("stats").textContent = `${side}×${side}, ${response.headers.get("X-Locus-Method")}: ` +
      `${(seconds * 1000).toFixed(1)} ms render, ${(performance.now() - started).toFixed(0)} ms ` +
      `round trip, ${undecided} undecided`;
    $("overlay").textContent = `${side}²`;
    state.frames += 1;
    document.body.dataset.frames = state.frames;
    document.body.dataset.level = level;
    updateCommand();
    if (level === 2 && state.method !== "default" && state.method !== "certified" && !animating) check();
  } catch (e) {
    if (e.name !== "AbortError") showError(String(e));
  } finally {
    if (inFlight === controller) {
      inFlight = null;
      if (pending !== null) { const next = pending; pending = null; requestFrame(next); }
    }
  }
}

// Refines to half and then full resolution once the user has stopped for a moment.
function refineSoon() {
  clearTimeout(refineTimer);
  refineTimer = setTimeout(async () => {
    if (animating) return;
    await requestFrame(1);
    if (!inFlight) requestFrame(2);
  }, 150);
}

function interactiveFrame() {
  requestFrame(0);
  refineSoon();
}

async function check() {
  const response = await fetch("/api/check", { method: "POST", body: form(SIDE, { client: client + "-check" }) });
  if (!response.ok) return;
  const c = await response.json();
  $("stats").textContent += `; against certified: ${c.wrong} of ${c.rays} rays wrong`;
}

function updateCommand() {
  let equation = state.equation;
  for (const p of state.parameters) {
    equation = equation.replace(new RegExp(`\\b${p.name}\\b`, "g"), `(${Number(p.value)})`);
  }
  const c = state.camera;
  const fmt = (v) => v.map((x) => Number(Number(x.toFixed(6)).toPrecision(6))).join(",");
  let command = state.source === "startup" ? "locus render SCENE" : `locus render '${equation}'`;
  command += ` --size ${SIDE}x${SIDE}`;
  if (c) command += ` --eye ${fmt(c.eye)} --target ${fmt(c.target)} --up ${fmt(c.up)} --fov ${Number(c.fov.toPrecision(4))}`;
  if (state.method !== "default") command += ` --method ${state.method}`;
  if (!$("shadows").checked) command += " --shadows off";
  command += " -o locus-view.png";
  $("command").textContent = command;
}

function buildSliders(names) {
  const old = new Map(state.parameters.map((p) => [p.name, p]));
  state.parameters = names.map((name) => old.get(name) || { name, min: -2, max: 2, value: 1 });
  const box = $("params");
  box.textContent = "";
  for (const p of state.parameters) {
    const row = document.createElement("div");
    row.className = "param";
    row.innerHTML = `<span>${p.name}</span><input type="number" step="any" value="${p.min}" title="from">` +
      `<input type="range" id="param-${p.name}" min="${p.min}" max="${p.max}" step="any" value="${p.value}">` +
      `<input type="number" step="any" value="${p.max}" title="to">` +
      `<input type="number" step="any" id="value-${p.name}" value="${p.value}" title="value">` +
      `<button title="animate">▶</button>`;
    const [, low, slider, high, value, play] = row.children;
    const show = () => { value.value = Number(Number(p.value).toPrecision(4)); };
    slider.addEventListener("input", () => { p.value = Number(slider.value); show(); interactiveFrame(); });
    value.addEventListener("change", () => {
      p.value = Number(value.value);
      if (p.value < p.min) { p.min = p.value; low.value = p.value; slider.min = p.value; }
      if (p.value > p.max) { p.max = p.value; high.value = p.value; slider.max = p.value; }
      slider.value = p.value;
      requestFrame(2);
    });
    low.addEventListener("change", () => { p.min = Number(low.value); slider.min = low.value; });
    high.addEventListener("change", () => { p.max = Number(high.value); slider.max = high.value; });
    play.addEventListener("click", () => animate(p, slider, play, show));
    box.appendChild(row);
  }
}

// Sweeps one parameter back and forth, one quarter-resolution frame after another.
function animate(p, slider, button, show) {
  if (animating) { animating = null; button.textContent = "▶"; refineSoon(); return; }
  button.textContent = "■";
  let direction = 1;
  animating = p.name;
  const step = async () => {
    if (animating !== p.name) return;
    let v = Number(p.value) + direction * (p.max - p.min) / 60;
    if (v > p.max || v < p.min) { direction = -direction; v = Math.min(p.max, Math.max(p.min, v)); }
    p.value = v;
    slider.value = v;
    show();
    await requestFrame(0);
    requestAnimationFrame(step);
  };
  step();
}

async function applyEquation() {
  const text = $("equation").value.trim();
  const response = await fetch("/api/parse", { method: "POST", body: new URLSearchParams({ equation: text }) });
  const answer = await response.json();
  if (!response.ok) {
    state.equation = text;
    showError(answer.error, answer.column);
    return;
  }
  showError("");
  const changed = text !== state.equation || state.source !== "equation";
  state.source = "equation";
  state.equation = text;
  buildSliders(answer.parameters);
  if (changed) state.camera = null;
  requestFrame(2);
}

function setupInteraction() {
  const img = $("view");
  let last = null;
  img.addEventListener("pointerdown", (e) => {
    if (!state.camera) return;
    last = [e.clientX, e.clientY];
    img.setPointerCapture(e.pointerId);
    img.classList.add("dragging");
  });
  img.addEventListener("pointermove", (e) => {
    if (!last || !state.camera) return;
    const dx = e.clientX - last[0], dy = e.clientY - last[1];
    last = [e.clientX, e.clientY];
    const c = state.camera;
    const up = norm(c.up);
    let offset = sub(c.eye, c.target);
    offset = rotate(offset, up, -dx * 0.01);                      // about the up axis
    const right = norm(cross(up, offset));
    const turned = rotate(offset, right, dy * 0.01);               // over the top, not past it
    if (Math.abs(dot(norm(turned), up)) < 0.98) offset = turned;
    c.eye = add(c.target, offset);
    interactiveFrame();
  });
  const end = () => { last = null; img.classList.remove("dragging"); };
  img.addEventListener("pointerup", end);
  img.addEventListener("pointercancel", end);
  img.addEventListener("wheel", (e) => {
    if (!state.camera) return;
    e.preventDefault();
    const c = state.camera;
    c.eye = add(c.target, scale(sub(c.eye, c.target), Math.exp(e.deltaY * 0.001)));
    interactiveFrame();
  }, { passive: false });
  img.addEventListener("dblclick", async (e) => {
    if (!state.camera) return;
    const r = img.getBoundingClientRect();
    const x = Math.floor((e.clientX - r.left) / r.width * SIDE), y = Math.floor((e.clientY - r.top) / r.height * SIDE);
    const response = await fetch("/api/pick", { method: "POST", body: form(SIDE, { x, y, shadows: "0" }) });
    const answer = await response.json();
    if (!answer.hit) return;
    const c = state.camera;
    const move = sub(answer.point, c.target);
    c.target = answer.point;
    c.eye = add(c.eye, move);
    requestFrame(2);
  });
}

async function start() {
  const startup = await (await fetch("/api/startup")).json();
  for (const m of ["default", ...startup.methods]) {
    const o = document.createElement("option");
    o.value = o.textContent = m;
    $("method").appendChild(o);
  }
  $("equation").maxLength = startup.max_equation;
  if (startup.label !== undefined) {
    document.title = `locus view: ${startup.label}`;
    if (startup.scene) {
      state.source = "startup";
      $("equation").placeholder = `${startup.label} (type an equation to replace it)`;
    } else {
      $("equation").value = startup.equation;
      state.equation = startup.equation;
      const parsed = await (await fetch("/api/parse", { method: "POST", body: new URLSearchParams({ equation: startup.equation }) })).json();
      buildSliders(parsed.parameters || []);
    }
  } else {
    $("equation").value = "x^4 + y^4 + z^4 - a*(x^2 + y^2 + z^2) + 0.5";
    await applyEquation();
    return;
  }
  requestFrame(2);
}

$("render").addEventListener("click", applyEquation);
$("equation").addEventListener("keydown", (e) => { if (e.key === "Enter" && e.ctrlKey) { e.preventDefault(); applyEquation(); } });
$("method").addEventListener("change", () => { state.method = $("method").value; requestFrame(2); });
for (const id of ["azimuth", "elevation", "front", "back"]) $(id).addEventListener("input", interactiveFrame);
$("shadows").addEventListener("change", () => requestFrame(2));
$("copy").addEventListener("click", () => { navigator.clipboard && navigator.clipboard.writeText($("command").textContent); });
$("implicitize").addEventListener("click", async () => {
  const response = await fetch("/api/implicitize", { method: "POST", body: new URLSearchParams({ param: $("param-text").value }) });
  const answer = await response.json();
  if (!response.ok) { showError(answer.error); return; }
  $("equation").value = answer.equation;
  applyEquation();
});
setupInteraction();
start();
