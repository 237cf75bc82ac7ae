// The web page in a real browser (Debian's Chromium, driven by playwright-core): it loads
// from a local server, builds the worked example and a catalogue variant, and every file it
// gives for download — the zip and a file downloaded alone — is byte-identical to what the
// command line writes for the same options; an invalid project shows its error with the
// line in the editor. Prints the timings (cold and warm, against the native CLI) as JSON.
//
//   node e2e.mjs --cli PATH/TO/tmm [--dist ../dist] [--timings FILE]
import { chromium } from "playwright-core";
import { execFileSync } from "node:child_process";
import { createServer } from "node:http";
import { mkdtempSync, readFileSync, readdirSync, writeFileSync, existsSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, extname, resolve, dirname } from "node:path";
import { fileURLToPath } from "node:url";
import { gzipSync } from "node:zlib";
import assert from "node:assert/strict";

const here = dirname(fileURLToPath(import.meta.url));
const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const cli = arg("--cli");
const dist = resolve(arg("--dist", join(here, "..", "dist")));
const timingsFile = arg("--timings");
assert.ok(cli, "--cli PATH: the tmm binary to compare with");
const chromiumPath = process.env.CHROMIUM || "/usr/bin/chromium";

// ---- a static server for web/dist ----------------------------------------------------
const TYPES = {
  ".html": "text/html; charset=utf-8",
  ".js": "text/javascript; charset=utf-8",
  ".css": "text/css; charset=utf-8",
  ".wasm": "application/wasm",
  ".ttf": "font/ttf",
};
const server = createServer((req, res) => {
  const path = decodeURIComponent(new URL(req.url, "http://x").pathname);
  const file = join(dist, path.endsWith("/") ? path + "index.html" : path);
  if (!file.startsWith(dist) || !existsSync(file)) {
    res.writeHead(404).end();
    return;
  }
  res.writeHead(200, { "content-type": TYPES[extname(file)] || "application/octet-stream" });
  res.end(readFileSync(file));
});
await new Promise((ok) => server.listen(0, "127.0.0.1", ok));
const base = `http://127.0.0.1:${server.address().port}/`;

// ---- what the command line writes ----------------------------------------------------
function cliFiles(args) {
  const dir = mkdtempSync(join(tmpdir(), "tmm-cli-"));
  const start = performance.now();
  execFileSync(cli, ["build", ...args, "-o", dir], { stdio: ["ignore", "ignore", "inherit"] });
  const ms = performance.now() - start;
  const files = new Map();
  for (const name of readdirSync(dir).filter((n) => !n.startsWith("."))) files.set(name, readFileSync(join(dir, name)));
  // Read into memory: the folder goes (every run left two behind in the temporary directory).
  rmSync(dir, { recursive: true, force: true });
  return { files, ms };
}

// A zip's entries, read by Python's zipfile (an independent reader, with its CRC checks).
function unzip(bytes) {
  const dir = mkdtempSync(join(tmpdir(), "tmm-zip-"));
  const zip = join(dir, "all.zip");
  writeFileSync(zip, bytes);
  const out = join(dir, "x");
  execFileSync("python3", ["-c", "import sys, zipfile; z = zipfile.ZipFile(sys.argv[1]); assert z.testzip() is None; z.extractall(sys.argv[2]); print('\\n'.join(z.namelist()))", zip, out]);
  const files = new Map();
  for (const name of readdirSync(out)) files.set(name, readFileSync(join(out, name)));
  rmSync(dir, { recursive: true, force: true });
  return files;
}

function assertSame(label, cliFiles, pageFiles) {
  assert.deepEqual([...pageFiles.keys()].sort(), [...cliFiles.keys()].sort(), `${label}: the same files`);
  for (const [name, bytes] of cliFiles) {
    assert.ok(Buffer.compare(bytes, pageFiles.get(name)) === 0, `${label}: ${name} differs from the command line's`);
  }
  console.log(`ok - ${label}: ${cliFiles.size} files byte-identical to the command line's`);
}

async function download(page, click) {
  const [d] = await Promise.all([page.waitForEvent("download"), click()]);
  return { name: d.suggestedFilename(), bytes: readFileSync(await d.path()) };
}

async function setChecks(page, checks) {
  for (const [selector, on] of Object.entries(checks)) await page.setChecked(selector, on);
}

// Builds with the page's current project and options; returns the time to the first sheet
// shown and to the last file, in ms, measured by the page.
async function build(page) {
  await page.click("#build");
  await page.waitForSelector("body[data-state=built], body[data-state=refused]", { timeout: 300000 });
  assert.equal(await page.getAttribute("body", "data-state"), "built", await page.textContent("#status"));
  return page.evaluate(() => ({ firstSheet: window.tmm.timings.firstSheet, done: window.tmm.timings.done }));
}

// The module itself, in Node: every variant of every task gives the project file
// `tmm init` writes (a 32-bit target once broke the longest template expression).
async function everyVariantAsInit() {
  const tmm = await import(join(dist, "pkg", "tmm_web.js"));
  tmm.initSync({ module: readFileSync(join(dist, "pkg", "tmm_web_bg.wasm")) });
  let n = 0;
  for (const task of JSON.parse(tmm.catalogue("en"))) {
    for (const v of task.variants.filter((v) => v.status !== "incomplete")) {
      const init = execFileSync(cli, ["init", "--task", task.id, "--variant", String(v.number), "--lang", "en"], {
        stdio: ["ignore", "pipe", "ignore"],
      });
      assert.equal(tmm.variant(task.id, v.number, "en"), init.toString(), `task ${task.id} variant ${v.number}`);
      n++;
    }
  }
  console.log(`ok - ${n} variants' project files in the module are tmm init's`);
}

const browser = await chromium.launch({
  executablePath: chromiumPath,
  args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking", "--disable-component-update", "--disable-sync"],
});
const timings = {};
let failed = false;
try {
  const context = await browser.newContext({ acceptDownloads: true, viewport: { width: 1600, height: 1000 } });
  const page = await context.newPage();
  const errors = [];
  page.on("pageerror", (e) => errors.push(String(e)));
  page.on("console", (m) => m.type() === "error" && errors.push(m.text()));

  await everyVariantAsInit();

  // Cold: from the navigation to the first sheet on the screen (fetching and compiling the
  // module included).
  await page.goto(base + "?lang=uz");
  await page.waitForSelector("body[data-state=ready]", { timeout: 120000 });
  assert.match(await page.inputValue("#text"), /title|mechanism/);
  await setChecks(page, { "#pdf": true, "#dxf": true, "#overlay": true });
  await page.selectOption("#dxf-version", "r2000");
  const cold = await build(page);
  const ready = await page.evaluate(() => window.tmm.readyAt);
  timings.cold_ready_ms = Math.round(ready);
  timings.cold_first_sheet_ms = Math.round(ready + cold.firstSheet);
  timings.cold_build_all_ms = Math.round(cold.done);
  // The sheet is drawn in the sheets' own font, with its text.
  assert.ok(await page.evaluate(() => document.fonts.check('12px "DejaVu Sans"')), "the sheets' font is loaded");
  assert.ok((await page.locator("#sheet-holder svg text").count()) > 100, "sheet 1 is shown with its text");

  const we = cliFiles(["--no-png", "--dxf", "--overlay"]);
  timings.cli_worked_example_ms = Math.round(we.ms);
  await page.click("#tabs button[data-tab=files]");
  const zip = await download(page, () => page.click("#zip"));
  assert.match(zip.name, /\.zip$/);
  assertSame("worked example (zip)", we.files, unzip(zip.bytes));
  const one = await download(page, () => page.click('#file-list a[data-file="sheet1.pdf"]'));
  assert.equal(one.name, "sheet1.pdf");
  assert.ok(Buffer.compare(one.bytes, we.files.get("sheet1.pdf")) === 0, "sheet1.pdf downloaded alone");
  console.log("ok - sheet1.pdf downloaded alone is the command line's");
  await page.click("#tabs button[data-tab=tables]");
  assert.ok((await page.locator("#tables table").count()) >= 10, "the note's tables are shown");

  // Warm: the module loaded, the same build again.
  const warm = await build(page);
  timings.warm_first_sheet_ms = Math.round(warm.firstSheet);
  timings.warm_build_all_ms = Math.round(warm.done);

  // A catalogue variant, in Russian, PDF and SVG only.
  await page.selectOption("#lang", "ru");
  await page.waitForFunction(() => document.querySelector("#task option") && document.documentElement.lang === "ru");
  await page.selectOption("#task", "7");
  await page.selectOption("#variant", "2");
  await page.click("#load-variant");
  await page.waitForFunction(() => document.querySelector("#text").value.includes("--task 7 --variant 2"));
  await setChecks(page, { "#pdf": true, "#dxf": false, "#overlay": false });
  await build(page);
  const variant = cliFiles(["--task", "7", "--variant", "2", "--lang", "ru", "--no-png"]);
  await page.click("#tabs button[data-tab=files]");
  const zip2 = await download(page, () => page.click("#zip"));
  assertSame("task 7 variant 2 in Russian (zip)", variant.files, unzip(zip2.bytes));

  // An invalid project: its error shown with the line, the line marked in the editor.
  const text = await page.inputValue("#text");
  const bad = text.replace(/\bmass: ([0-9.]+)/, "mass: -$1");
  assert.notEqual(bad, text, "the variant has a mass to spoil");
  const line = bad.slice(0, bad.indexOf("mass: -")).split("\n").length;
  await page.fill("#text", bad);
  await page.waitForSelector("#status.bad");
  const status = await page.textContent("#status");
  assert.ok(status.includes(`строка ${line},`), `the error names line ${line}: ${status}`);
  assert.equal(await page.textContent("#gutter .bad"), String(line), "the gutter marks the line");
  await page.click("#build");
  await page.waitForSelector("body[data-state=refused]");
  console.log(`ok - an invalid project shows its error at line ${line}: ${status}`);
  assert.deepEqual(errors, [], "no error in the page's console");
} catch (e) {
  failed = true;
  console.error(e);
} finally {
  await browser.close();
  server.close();
}
const wasm = readFileSync(join(dist, "pkg", "tmm_web_bg.wasm"));
timings.module_kib = Math.round(wasm.length / 1024);
timings.module_gzip_kib = Math.round(gzipSync(wasm, { level: 9 }).length / 1024);
console.log(JSON.stringify(timings));
if (timingsFile) writeFileSync(timingsFile, JSON.stringify(timings, null, 2) + "\n");
process.exit(failed ? 1 : 0);
