// The page: the project's editor, the choice of sheets and formats, the sheets shown with
// zoom and pan, the tables and the downloads. Everything the program computes comes from
// the worker (worker.js), which runs the Rust library compiled to WebAssembly.

const WORDS = {
  uz: {
    tagline: "MMN kurs loyihasining chizmalari, aniq hisoblangan",
    language: "Til",
    project: "Loyiha fayli",
    example: "Namunaviy misol",
    open: "Faylni ochish…",
    task: "Topshiriq",
    variant: "Variant",
    load: "Yuklash",
    "build-what": "Nimani qurish",
    sheet1: "1-varaq (richagli mexanizm)",
    sheet2: "2-varaq (tishli uzatmalar)",
    sheet3: "3-varaq (kulachok)",
    overlay: "Qurilishlar qatlami",
    build: "Qurish",
    fit: "Sigʻdirish",
    placeholder: "Loyihani tanlang va «Qurish» tugmasini bosing.",
    zip: "Hammasini yuklab olish (zip)",
    tables: "Jadvallar",
    files: "Fayllar",
    sheet: (n) => `${n}-varaq`,
    reads: (sheets) => `Loyiha oʻqildi: ${sheets.join(", ")}-varaq quriladi.`,
    building: (n) => `${n}-varaq qurilmoqda…`,
    finishing: "Natijalar yozilmoqda…",
    built: (n, s) => `Tayyor: ${n} ta fayl, ${s} s.`,
    line: (l, c) => `${l}-qator, ${c}-ustun`,
    refused: "Loyiha rad etildi",
    others: (s) => `Bu faqat ${s.blocks.join(", ")}-varaqni toʻxtatadi; qolganlarini (${s.others.join(", ")}) belgilab qurish mumkin.`,
    noSheet: "Kamida bitta varaqni tanlang.",
    status: { complete: "", partial: "qisman", incomplete: "toʻliq emas", refused: "rad etiladi" },
    loading: "Dastur yuklanmoqda…",
  },
  ru: {
    tagline: "Чертежи курсового проекта по ТММ, рассчитанные точно",
    language: "Язык",
    project: "Файл проекта",
    example: "Пример из пособия",
    open: "Открыть файл…",
    task: "Задание",
    variant: "Вариант",
    load: "Загрузить",
    "build-what": "Что построить",
    sheet1: "Лист 1 (рычажный механизм)",
    sheet2: "Лист 2 (зубчатые передачи)",
    sheet3: "Лист 3 (кулачок)",
    overlay: "Слой построений",
    build: "Построить",
    fit: "Вписать",
    placeholder: "Выберите проект и нажмите «Построить».",
    zip: "Скачать всё (zip)",
    tables: "Таблицы",
    files: "Файлы",
    sheet: (n) => `Лист ${n}`,
    reads: (sheets) => `Проект прочитан: будут построены листы ${sheets.join(", ")}.`,
    building: (n) => `Строится лист ${n}…`,
    finishing: "Записываются результаты…",
    built: (n, s) => `Готово: ${n} файлов, ${s} с.`,
    line: (l, c) => `строка ${l}, столбец ${c}`,
    refused: "Проект не принят",
    others: (s) => `Это мешает только листу ${s.blocks.join(", ")}; остальные (${s.others.join(", ")}) можно построить, выбрав их.`,
    noSheet: "Выберите хотя бы один лист.",
    status: { complete: "", partial: "частично", incomplete: "неполный", refused: "не принимается" },
    loading: "Загрузка программы…",
  },
  en: {
    tagline: "The TMM course project's sheets, computed exactly",
    language: "Language",
    project: "Project file",
    example: "Worked example",
    open: "Open a file…",
    task: "Task",
    variant: "Variant",
    load: "Load",
    "build-what": "What to build",
    sheet1: "Sheet 1 (lever mechanism)",
    sheet2: "Sheet 2 (gears)",
    sheet3: "Sheet 3 (cam)",
    overlay: "Constructions overlay",
    build: "Build",
    fit: "Fit",
    placeholder: "Choose a project and press Build.",
    zip: "Download all (zip)",
    tables: "Tables",
    files: "Files",
    sheet: (n) => `Sheet ${n}`,
    reads: (sheets) => `The project reads: sheet ${sheets.join(", ")} will be built.`,
    building: (n) => `Building sheet ${n}…`,
    finishing: "Writing the results…",
    built: (n, s) => `Done: ${n} files in ${s} s.`,
    line: (l, c) => `line ${l}, column ${c}`,
    refused: "The project was refused",
    others: (s) => `This refuses sheet ${s.blocks.join(", ")} only; tick the others (${s.others.join(", ")}) to build them.`,
    noSheet: "Tick at least one sheet.",
    status: { complete: "", partial: "in part", incomplete: "incomplete", refused: "refused as printed" },
    loading: "Loading the program…",
  },
};

const $ = (id) => document.getElementById(id);
const state = {
  lang: "uz",
  files: [], // {name, bytes} in the command line's order
  svgs: new Map(), // sheet number → SVG text
  tab: null,
  catalogue: [],
  problem: null,
  timings: {},
};
// For tests and for the curious: the last build's files and timings.
window.tmm = state;

// ---- the worker ----------------------------------------------------------------------
const worker = new Worker(new URL("./worker.js", import.meta.url), { type: "module" });
let nextId = 1;
const pending = new Map();
worker.onmessage = (event) => {
  const m = event.data;
  const p = pending.get(m.id);
  if (!p) return;
  if (m.progress) return p.onProgress && p.onProgress(m.progress);
  pending.delete(m.id);
  if (m.ok) p.resolve(m.result);
  else p.reject(m.problem);
};
function call(cmd, args = {}, onProgress) {
  const id = nextId++;
  return new Promise((resolve, reject) => {
    pending.set(id, { resolve, reject, onProgress });
    worker.postMessage({ id, cmd, ...args });
  });
}

const w = () => WORDS[state.lang];

// ---- words -------------------------------------------------------------------------
function translate() {
  document.documentElement.lang = state.lang;
  for (const el of document.querySelectorAll("[data-t]")) {
    const v = w()[el.dataset.t];
    if (typeof v === "string") el.textContent = v;
  }
  renderTabs();
  showStatus();
}

// ---- the editor --------------------------------------------------------------------
const text = $("text");
const gutter = $("gutter");

function renderGutter() {
  const lines = text.value.split("\n").length;
  const bad = state.problem && state.problem.line;
  const warned = new Set((state.notes || []).map((n) => n.line).filter((l) => l > 0));
  const out = [];
  for (let i = 1; i <= lines; i++) {
    const cls = i === bad ? "bad" : warned.has(i) ? "warn" : "";
    out.push(cls ? `<span class="${cls}">${i}</span>` : String(i));
  }
  gutter.innerHTML = out.join("\n") + "\n";
  gutter.scrollTop = text.scrollTop;
}
text.addEventListener("scroll", () => (gutter.scrollTop = text.scrollTop));

// Puts the cursor at a line and column of the file and scrolls to it.
function goTo(line, column) {
  if (!line) return;
  const lines = text.value.split("\n");
  let offset = 0;
  for (let i = 0; i < line - 1 && i < lines.length; i++) offset += lines[i].length + 1;
  offset += Math.max(0, (column || 1) - 1);
  text.focus();
  text.setSelectionRange(offset, Math.min(text.value.length, offset + 1));
  const lineHeight = parseFloat(getComputedStyle(text).lineHeight) || 18;
  text.scrollTop = Math.max(0, (line - 4) * lineHeight);
}

function selectedSheets() {
  return [...document.querySelectorAll("#sheets input:checked")].map((i) => Number(i.value));
}

function options() {
  return {
    sheets: selectedSheets(),
    lang: state.lang,
    pdf: $("pdf").checked,
    dxf: $("dxf").checked ? $("dxf-version").value : "",
    overlay: $("overlay").checked,
  };
}

function showStatus() {
  const status = $("status");
  const list = $("warnings");
  list.innerHTML = "";
  status.className = "";
  status.onclick = null;
  const p = state.problem;
  if (p) {
    status.className = "bad";
    const where = p.line ? `${w().line(p.line, p.column)}: ` : "";
    const field = p.field ? `${p.field}: ` : "";
    status.textContent = `${w().refused} — ${where}${field}${p.cause}`;
    const others = (p.buildable || []).filter((n) => !(p.blocks || []).includes(n));
    if (others.length && p.blocks && p.blocks.length) {
      const hint = document.createElement("div");
      hint.className = "hint";
      hint.textContent = w().others({ blocks: p.blocks, others });
      status.appendChild(hint);
    }
    status.onclick = () => goTo(p.line, p.column);
  } else if (state.readSheets) {
    status.className = "ok";
    status.textContent = state.readSheets.length ? w().reads(state.readSheets) : w().noSheet;
  }
  for (const n of state.notes || []) {
    const li = document.createElement("li");
    li.textContent = n.line ? `${w().line(n.line, n.column)}: ${n.field}: ${n.message.replace(/^line \d+, column \d+: [^:]*: /, "")}` : n.message;
    li.onclick = () => goTo(n.line, n.column);
    list.appendChild(li);
  }
}

let validateTimer = null;
let validation = 0;
async function validate() {
  const mine = ++validation;
  const sheets = selectedSheets();
  if (!sheets.length) {
    Object.assign(state, { problem: null, notes: [], readSheets: [] });
  } else {
    try {
      const r = await call("validate", { text: text.value, options: options() });
      if (mine !== validation) return;
      state.problem = r.ok ? null : r.problem;
      state.notes = r.ok ? r.notes : [];
      state.readSheets = r.ok ? r.sheets : null;
    } catch (p) {
      state.problem = p;
    }
  }
  renderGutter();
  showStatus();
}
function validateSoon() {
  clearTimeout(validateTimer);
  validateTimer = setTimeout(validate, 300);
}
text.addEventListener("input", () => {
  renderGutter();
  validateSoon();
});

function setText(value) {
  text.value = value;
  text.scrollTop = 0;
  renderGutter();
  validate();
}

// ---- the catalogue -------------------------------------------------------------------
async function loadCatalogue() {
  state.catalogue = await call("catalogue", { lang: state.lang });
  const task = $("task");
  const keep = task.value;
  task.innerHTML = "";
  for (const t of state.catalogue) {
    const o = document.createElement("option");
    o.value = t.id;
    o.textContent = `${t.id}. ${t.name}`;
    task.appendChild(o);
  }
  if (keep) task.value = keep;
  fillVariants();
}

function fillVariants() {
  const t = state.catalogue.find((t) => t.id === $("task").value);
  const variant = $("variant");
  const keep = variant.value;
  variant.innerHTML = "";
  for (const v of t ? t.variants : []) {
    const o = document.createElement("option");
    o.value = v.number;
    const s = w().status[v.status];
    o.textContent = s ? `${v.number} (${s})` : String(v.number);
    o.disabled = v.status === "incomplete";
    variant.appendChild(o);
  }
  if (keep && [...variant.options].some((o) => o.value === keep && !o.disabled)) variant.value = keep;
  else {
    const first = [...variant.options].find((o) => !o.disabled);
    if (first) variant.value = first.value;
  }
  showVariantNote();
}

function showVariantNote() {
  const t = state.catalogue.find((t) => t.id === $("task").value);
  const v = t && t.variants.find((v) => String(v.number) === $("variant").value);
  $("variant-note").textContent = v && v.note ? v.note : "";
}

$("task").addEventListener("change", fillVariants);
$("variant").addEventListener("change", showVariantNote);
$("load-variant").addEventListener("click", async () => {
  try {
    setText(await call("variant", { task: $("task").value, variant: Number($("variant").value), lang: state.lang }));
  } catch (p) {
    state.problem = p;
    showStatus();
  }
});
$("example").addEventListener("click", async () => setText(await call("example")));
$("file").addEventListener("change", async (e) => {
  const f = e.target.files[0];
  if (f) setText(await f.text());
  e.target.value = "";
});
for (const id of ["pdf", "dxf", "dxf-version", "overlay"]) $(id).addEventListener("change", validateSoon);
$("sheets").addEventListener("change", validateSoon);

// ---- building ----------------------------------------------------------------------
const MIME = {
  svg: "image/svg+xml",
  pdf: "application/pdf",
  dxf: "application/dxf",
  csv: "text/csv;charset=utf-8",
  md: "text/markdown;charset=utf-8",
  json: "application/json",
  zip: "application/zip",
};
const decoder = new TextDecoder();

function addFiles(files) {
  for (const f of files) {
    state.files.push(f);
    const m = f.name.match(/^sheet(\d)\.svg$/);
    if (m) {
      state.svgs.set(Number(m[1]), decoder.decode(f.bytes));
      if (state.tab === null) {
        state.tab = Number(m[1]);
        state.timings.firstSheet = performance.now() - state.timings.start;
      }
    }
  }
  renderTabs();
  if (state.tab !== null && typeof state.tab === "number" && !$("sheet-holder").firstChild) showTab(state.tab);
}

async function build() {
  const opts = options();
  if (!opts.sheets.length) {
    state.problem = null;
    state.readSheets = [];
    return showStatus();
  }
  $("build").disabled = true;
  const bar = $("progress");
  const label = $("progress-text");
  bar.hidden = false;
  bar.value = 0;
  Object.assign(state, { files: [], svgs: new Map(), tab: null, timings: { start: performance.now() } });
  $("sheet-holder").innerHTML = "";
  $("placeholder").hidden = true;
  document.body.dataset.state = "building";
  try {
    const result = await call("build", { text: text.value, options: opts }, (p) => {
      bar.value = p.step / p.total;
      label.textContent = p.sheet && !p.files ? w().building(p.sheet) : w().finishing;
      if (p.files) addFiles(p.files);
    });
    addFiles(result.files);
    state.problem = null;
    state.notes = result.notes;
    state.title = result.title;
    state.timings.done = performance.now() - state.timings.start;
    label.textContent = w().built(state.files.length, (state.timings.done / 1000).toFixed(1));
    document.body.dataset.state = "built";
  } catch (p) {
    state.problem = p;
    label.textContent = "";
    document.body.dataset.state = "refused";
    if (!state.files.length) $("placeholder").hidden = false;
  }
  bar.hidden = true;
  $("build").disabled = false;
  renderGutter();
  showStatus();
  renderFiles();
  renderTables();
}
$("build").addEventListener("click", build);

// ---- tabs and the sheet view ---------------------------------------------------------
function renderTabs() {
  const tabs = $("tabs");
  tabs.innerHTML = "";
  const items = [...state.svgs.keys()].map((n) => [n, w().sheet(n)]);
  if (state.files.length) items.push(["tables", w().tables], ["files", w().files]);
  for (const [key, name] of items) {
    const b = document.createElement("button");
    b.type = "button";
    b.role = "tab";
    b.textContent = name;
    b.dataset.tab = key;
    b.setAttribute("aria-selected", String(key === state.tab));
    b.onclick = () => showTab(key);
    tabs.appendChild(b);
  }
}

function showTab(key) {
  state.tab = key;
  const sheet = typeof key === "number";
  $("view").hidden = !sheet;
  $("tables").hidden = key !== "tables";
  $("files").hidden = key !== "files";
  $("zoom").hidden = !sheet;
  if (sheet) {
    const holder = $("sheet-holder");
    const doc = new DOMParser().parseFromString(state.svgs.get(key), "image/svg+xml");
    const svg = document.importNode(doc.documentElement, true);
    const [, , width, height] = svg.getAttribute("viewBox").split(/\s+/).map(Number);
    view.paper = { width, height };
    svg.removeAttribute("width");
    svg.removeAttribute("height");
    holder.replaceChildren(svg);
    fit();
  }
  renderTabs();
}

// Zoom and pan: the sheet is laid out at `scale` px per mm (drawn sharp at every zoom).
const view = { scale: 1, x: 0, y: 0, paper: { width: 841, height: 594 } };
function place() {
  const h = $("sheet-holder");
  h.style.width = `${view.paper.width * view.scale}px`;
  h.style.height = `${view.paper.height * view.scale}px`;
  h.style.left = `${view.x}px`;
  h.style.top = `${view.y}px`;
}
function fit() {
  const vp = $("viewport");
  const s = Math.min(vp.clientWidth / view.paper.width, vp.clientHeight / view.paper.height) * 0.96;
  view.scale = s;
  view.x = (vp.clientWidth - view.paper.width * s) / 2;
  view.y = (vp.clientHeight - view.paper.height * s) / 2;
  place();
}
function zoomAt(factor, cx, cy) {
  const s = Math.min(40, Math.max(0.2, view.scale * factor));
  const k = s / view.scale;
  view.x = cx - (cx - view.x) * k;
  view.y = cy - (cy - view.y) * k;
  view.scale = s;
  place();
}
const vp = $("viewport");
vp.addEventListener(
  "wheel",
  (e) => {
    e.preventDefault();
    const r = vp.getBoundingClientRect();
    zoomAt(Math.exp(-e.deltaY * 0.0015), e.clientX - r.left, e.clientY - r.top);
  },
  { passive: false },
);
let drag = null;
vp.addEventListener("pointerdown", (e) => {
  drag = { x: e.clientX - view.x, y: e.clientY - view.y };
  vp.setPointerCapture(e.pointerId);
  vp.classList.add("dragging");
});
vp.addEventListener("pointermove", (e) => {
  if (!drag) return;
  view.x = e.clientX - drag.x;
  view.y = e.clientY - drag.y;
  place();
});
vp.addEventListener("pointerup", () => {
  drag = null;
  vp.classList.remove("dragging");
});
const centre = () => [vp.clientWidth / 2, vp.clientHeight / 2];
$("zoom-in").onclick = () => zoomAt(1.4, ...centre());
$("zoom-out").onclick = () => zoomAt(1 / 1.4, ...centre());
$("zoom-fit").onclick = fit;
window.addEventListener("resize", () => typeof state.tab === "number" && fit());

// ---- tables (from the Markdown the program writes) -----------------------------------
// Only the program's own markup is kept (<sub>, <sup>); everything else is shown as text.
function cellHtml(s) {
  const escaped = s
    .replace(/<a id="[^"]*"><\/a>/g, "")
    .replace(/&/g, "&amp;")
    .replace(/</g, "&lt;")
    .replace(/>/g, "&gt;");
  return escaped.replace(/&lt;(\/?)(sub|sup)&gt;/g, "<$1$2>").replace(/\\\|/g, "|");
}
function splitRow(line) {
  const cells = [];
  let cur = "";
  for (let i = 1; i < line.length; i++) {
    if (line[i] === "\\" && line[i + 1] === "|") {
      cur += "\\|";
      i++;
    } else if (line[i] === "|") {
      cells.push(cur.trim());
      cur = "";
    } else cur += line[i];
  }
  return cells;
}
function markdownTables(md) {
  const out = [];
  const lines = md.split("\n");
  for (let i = 0; i < lines.length; i++) {
    const line = lines[i];
    if (line.startsWith("### ")) out.push(`<h3>${cellHtml(line.slice(4))}</h3>`);
    else if (line.startsWith("|") && lines[i + 1] && /^\|[-:| ]+\|$/.test(lines[i + 1])) {
      const right = splitRow(lines[i + 1]).map((c) => c.endsWith(":"));
      const head = splitRow(line).map((c) => `<th>${cellHtml(c)}</th>`).join("");
      const rows = [];
      i += 2;
      for (; i < lines.length && lines[i].startsWith("|"); i++) {
        const cells = splitRow(lines[i]).map((c, k) => `<td${right[k] ? ' class="num"' : ""}>${cellHtml(c)}</td>`);
        rows.push(`<tr>${cells.join("")}</tr>`);
      }
      i--;
      out.push(`<table><thead><tr>${head}</tr></thead><tbody>${rows.join("")}</tbody></table>`);
    } else if (line.trim() && !line.startsWith("<a id=")) out.push(`<p>${cellHtml(line)}</p>`);
  }
  return out.join("\n");
}
function renderTables() {
  const parts = state.files
    .filter((f) => /-tables\.md$/.test(f.name))
    .map((f) => `<h2>${w().sheet(f.name.match(/^sheet(\d)/)[1])}</h2>` + markdownTables(decoder.decode(f.bytes)));
  $("tables").innerHTML = parts.join("\n");
}

// ---- downloads -----------------------------------------------------------------------
function download(name, bytes) {
  const ext = name.split(".").pop();
  const url = URL.createObjectURL(new Blob([bytes], { type: MIME[ext] || "application/octet-stream" }));
  const a = document.createElement("a");
  a.href = url;
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10000);
}
function size(n) {
  return n >= 1048576 ? `${(n / 1048576).toFixed(1)} MB` : `${Math.max(1, Math.round(n / 1024))} KB`;
}
function renderFiles() {
  const list = $("file-list");
  list.innerHTML = "";
  for (const f of state.files) {
    const li = document.createElement("li");
    const a = document.createElement("a");
    a.href = "#";
    a.textContent = f.name;
    a.dataset.file = f.name;
    a.onclick = (e) => {
      e.preventDefault();
      download(f.name, f.bytes);
    };
    const s = document.createElement("span");
    s.className = "size";
    s.textContent = size(f.bytes.length);
    li.append(a, s);
    list.appendChild(li);
  }
}
$("zip").addEventListener("click", async () => {
  const bytes = await call("zip");
  const stem = (state.title || "tmm-sheets").replace(/[\\/:*?"<>|\s]+/g, "-").replace(/^-+|-+$/g, "") || "tmm-sheets";
  download(`${stem}.zip`, bytes);
});

// ---- start -------------------------------------------------------------------------
$("lang").addEventListener("change", async (e) => {
  state.lang = e.target.value;
  localStorage.setItem("tmm-lang", state.lang);
  translate();
  await loadCatalogue();
  validateSoon();
});

async function start() {
  const params = new URLSearchParams(location.search);
  const lang = params.get("lang") || localStorage.getItem("tmm-lang") || "uz";
  state.lang = WORDS[lang] ? lang : "uz";
  $("lang").value = state.lang;
  translate();
  $("progress-text").textContent = w().loading;
  setText(await call("example"));
  await loadCatalogue();
  $("progress-text").textContent = "";
  document.body.dataset.state = "ready";
  state.readyAt = performance.now();
}
start();
