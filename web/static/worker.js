// The program runs here, off the page's thread, so that the page never freezes while a
// sheet is built. Messages in: {id, cmd, ...}; out: {id, progress} while building, then
// {id, ok: true, result} or {id, ok: false, problem}. Files leave as transferred buffers.
import init, * as tmm from "./pkg/tmm_web.js";

const ready = init();
let lastJob = null;

// A refusal thrown by the module is the JSON of a session::Problem; anything else is a bug
// (shown as it is, never swallowed).
function problemOf(e) {
  const text = typeof e === "string" ? e : String(e && e.message ? e.message : e);
  try {
    const p = JSON.parse(text);
    if (p && typeof p === "object" && "kind" in p) return p;
  } catch (_) {
    /* not JSON: a plain message */
  }
  return { kind: "error", line: 0, column: 0, field: "", cause: text, message: text, blocks: [], buildable: [] };
}

const handlers = {
  example: () => tmm.example(),
  catalogue: (m) => JSON.parse(tmm.catalogue(m.lang)),
  variant: (m) => tmm.variant(m.task, m.variant, m.lang),
  validate: (m) => JSON.parse(tmm.validate(m.text, JSON.stringify(m.options))),
  build: (m, progress) => {
    if (lastJob) lastJob.free();
    lastJob = null;
    const job = new tmm.Job(m.text, JSON.stringify(m.options));
    const sheets = Array.from(job.sheets());
    const total = sheets.length + 1;
    sheets.forEach((n, i) => {
      progress({ step: i, total, sheet: n });
      const before = job.count();
      job.build_sheet(n);
      // Each sheet is shown as soon as it is built.
      const files = [];
      for (let k = before; k < job.count(); k++) files.push({ name: job.name(k), bytes: job.bytes(k) });
      progress({ step: i + 1, total, sheet: n, files });
    });
    const before = job.count();
    job.finish();
    lastJob = job;
    // The sheets' files went with the progress; these are results.json and the overlays.
    const files = [];
    for (let k = before; k < job.count(); k++) files.push({ name: job.name(k), bytes: job.bytes(k) });
    return { title: job.title(), notes: JSON.parse(job.notes()), files };
  },
  zip: () => {
    if (!lastJob) throw new Error("nothing built yet");
    return lastJob.zip();
  },
};

self.onmessage = async (event) => {
  const m = event.data;
  const post = (msg) => {
    const buffers = [];
    const collect = (files) => files && files.forEach((f) => buffers.push(f.bytes.buffer));
    if (msg.progress) collect(msg.progress.files);
    if (msg.result && msg.result.files) collect(msg.result.files);
    if (msg.result instanceof Uint8Array) buffers.push(msg.result.buffer);
    self.postMessage(msg, buffers);
  };
  try {
    await ready;
    const handler = handlers[m.cmd];
    if (!handler) throw new Error(`unknown command ${m.cmd}`);
    const result = handler(m, (progress) => post({ id: m.id, progress }));
    post({ id: m.id, ok: true, result });
  } catch (e) {
    post({ id: m.id, ok: false, problem: problemOf(e) });
  }
};
