// The review page: load a case, ask for a plan, read it, give feedback or approve, look at the paths.
"use strict";

const TOKEN = new URLSearchParams(location.search).get("token") || "";
const state = { caseData: null, session: null, polling: null };
const $ = (id) => document.getElementById(id);

async function api(path, options = {}) {
  const headers = Object.assign({ "X-Trajadapt-Token": TOKEN }, options.headers || {});
  let response;
  try {
    response = await fetch(path, Object.assign({}, options, { headers }));
  } catch (err) {
    throw new Error("the server cannot be reached (" + err.message + ")");
  }
  const text = await response.text();
  let data = null;
  try { data = JSON.parse(text); } catch (err) { data = null; }
  if (!response.ok) throw new Error((data && data.error) || ("the server answered " + response.status));
  return data;
}

function showError(message) {
  const box = $("error");
  box.textContent = message || "";
  box.hidden = !message;
}

async function guarded(action) {
  showError("");
  try { await action(); } catch (err) { showError(err.message); }
}

// ---- cases -------------------------------------------------------------------------------------

async function loadCaseList() {
  const data = await api("/api/cases");
  for (const name of data.cases) {
    const option = document.createElement("option");
    option.value = option.textContent = name;
    $("case-list").appendChild(option);
  }
}

function useCase(data) {
  state.caseData = data;
  state.session = null;
  $("case-name").textContent = data.name + ": " + data.trajectory.length + " waypoints, " + data.objects.length + " objects";
  $("instruction").value = data.instruction || "";
  $("ask").disabled = false;
  $("plan-box").hidden = $("result-box").hidden = $("history-box").hidden = true;
  drawPaths(data, null);
}

$("case-list").addEventListener("change", () => guarded(async () => {
  const name = $("case-list").value;
  if (name) useCase(await api("/api/cases/" + encodeURIComponent(name).replace(/%2F/g, "/")));
}));

$("case-file").addEventListener("change", () => guarded(async () => {
  const file = $("case-file").files[0];
  if (!file) return;
  const text = await file.text();
  useCase(await api("/api/upload?name=" + encodeURIComponent(file.name), { method: "POST", body: text,
    headers: { "Content-Type": "application/json" } }));
}));

// ---- sessions ----------------------------------------------------------------------------------

// The Limits fields as the API's ``limits``: empty fields are left out (the server's defaults hold).
function limits() {
  const number = (id) => ($(id).value === "" ? null : Number($(id).value));
  const box = $("limit-workspace").value.trim();
  const workspace = box ? box.split(/[\s,]+/).map(Number) : null;
  if (workspace && workspace.length !== 6) throw new Error("the workspace box needs six numbers");
  return { robot: $("limit-robot").value || null, clearance: number("limit-clearance"),
    max_speed: number("limit-max-speed"), workspace, fixed_ends: $("limit-fixed-ends").value };
}

$("ask").addEventListener("click", () => guarded(async () => {
  const body = { case: state.caseData, instruction: $("instruction").value, name: state.caseData.name,
    limits: limits() };
  follow(await post("/api/sessions", body));
}));

$("send-feedback").addEventListener("click", () => guarded(async () => {
  follow(await post("/api/sessions/" + state.session.id + "/feedback",
    { text: $("feedback").value, on: $("feedback-on").value }));
  $("feedback").value = "";
}));

$("approve").addEventListener("click", () => guarded(async () => {
  follow(await post("/api/sessions/" + state.session.id + "/approve", {}));
}));

$("cancel").addEventListener("click", () => guarded(async () => {
  follow(await post("/api/sessions/" + state.session.id + "/cancel", {}));
}));

$("simulate").addEventListener("click", () => guarded(async () => {
  follow(await post("/api/sessions/" + state.session.id + "/simulate", { robot: $("robot").value }));
}));

function post(path, body) {
  return api(path, { method: "POST", body: JSON.stringify(body), headers: { "Content-Type": "application/json" } });
}

function follow(session) {
  render(session);
  clearTimeout(state.polling);
  if (session.status === "working") {
    state.polling = setTimeout(() => guarded(async () => follow(await api("/api/sessions/" + session.id))), 400);
  } else {
    loadSessions();
  }
}

function render(session) {
  state.session = session;
  state.caseData = session.case;
  $("busy").hidden = session.status !== "working";
  $("activity").textContent = session.activity;
  $("elapsed").textContent = session.status === "working" ? "(" + session.elapsed_s.toFixed(0) + " s)" : "";
  if (session.error) showError(session.error);
  const version = session.versions[session.current];
  $("plan-box").hidden = !version;
  const editable = session.live && session.status !== "working";
  for (const id of ["send-feedback", "approve", "feedback", "feedback-on"]) $(id).disabled = !editable;
  $("feedback-on").options[1].disabled = !session.result;
  if (!session.result) $("feedback-on").value = "original";
  if (version) renderVersion(version, session);
  renderMemory(session);
  renderHistory(session);
  renderResult(session);
  const proposed = session.result && session.result.modified_trajectory ? session.result.modified_trajectory
    : (version ? version.proposed : null);
  drawPaths(session.case, proposed);
}

function renderVersion(version, session) {
  $("version-label").textContent = "(version " + (version.index + 1) + " of " + session.versions.length + ")";
  $("plan").replaceChildren(...version.steps.map((step) => {
    const item = document.createElement("li");
    item.textContent = step.replace(/^\s*\d+[.)]\s*/, "");
    return item;
  }));
  $("code").innerHTML = highlight(version.code);
  const lines = version.explanation || [];
  $("explanation-box").hidden = lines.length === 0;
  $("explanation").replaceChildren(...lines.map((line) => {
    const item = document.createElement("li");
    item.textContent = line;
    return item;
  }));
  $("problem").hidden = !version.problem;
  $("problem").textContent = version.problem ? "The code does not run yet: " + version.problem : "";
}

function renderHistory(session) {
  $("history-box").hidden = session.versions.length === 0;
  $("history").replaceChildren(...session.versions.map((version) => {
    const item = document.createElement("li");
    const kind = version.index === 0 ? "Instruction: " : (version.on === "current" ? "On the result: " : "Feedback: ");
    item.textContent = kind + version.request + " → " +
      version.steps.length + "-step plan ";
    if (session.live && version.index < session.versions.length - 1 && session.status !== "working") {
      const button = document.createElement("button");
      button.textContent = "Undo to version " + (version.index + 1);
      button.className = "undo";
      button.addEventListener("click", () => guarded(async () => {
        follow(await post("/api/sessions/" + session.id + "/undo", { version: version.index }));
      }));
      item.appendChild(button);
    }
    return item;
  }));
}

function forgetButton(session, exampleId) {
  const button = document.createElement("button");
  button.textContent = "Forget this one";
  button.addEventListener("click", () => guarded(async () => {
    follow(await post("/api/sessions/" + session.id + "/forget", { example: exampleId }));
  }));
  return button;
}

function renderMemory(session) {
  const memory = session.memory || { recalled: [], remembered_as: "" };
  $("recalled-box").hidden = memory.recalled.length === 0;
  $("recalled").replaceChildren(...memory.recalled.map((example) => {
    const item = document.createElement("li");
    item.textContent = example.instruction + " ";
    if (session.live) item.appendChild(forgetButton(session, example.id));
    return item;
  }));
  $("remembered-box").hidden = !memory.remembered_as;
  const old = $("forget-result");
  const fresh = forgetButton(session, memory.remembered_as);
  fresh.id = "forget-result";
  old.replaceWith(fresh);
}

function renderResult(session) {
  const result = session.result;
  $("result-box").hidden = !result;
  if (!result) return;
  $("result-status").textContent = "Approved: " + result.modified_trajectory.length + " waypoints (status " + result.status + ")";
  const effect = result.effect || { in_words: [], contradictions: [] };
  $("effect").replaceChildren(...effect.in_words.map((line) => {
    const item = document.createElement("li");
    item.textContent = line;
    return item;
  }));
  $("contradictions").hidden = effect.contradictions.length === 0;
  $("contradictions").replaceChildren(...effect.contradictions.map((line) => {
    const item = document.createElement("li");
    item.textContent = "Check this: " + line;
    return item;
  }));
  $("download").href = "/api/sessions/" + session.id + "/result" + (TOKEN ? "?token=" + encodeURIComponent(TOKEN) : "");
  const sim = session.simulation;
  $("sim-summary").textContent = sim ? sim.summary.join("\n") : "";
  $("sim-summary").hidden = !sim;
  $("sim-media").replaceChildren();
  if (sim) {
    for (const name of [sim.image, sim.animation]) {
      const img = document.createElement("img");
      img.src = "/api/sessions/" + session.id + "/files/" + name + (TOKEN ? "?token=" + encodeURIComponent(TOKEN) : "");
      img.alt = name;
      $("sim-media").appendChild(img);
    }
  }
}

async function loadSessions() {
  const data = await api("/api/sessions");
  $("sessions").replaceChildren(...data.sessions.slice(0, 30).map((s) => {
    const item = document.createElement("li");
    const link = document.createElement("a");
    link.textContent = (s.case_name || "case") + ": " + (s.instruction || "");
    link.addEventListener("click", () => guarded(async () => follow(await api("/api/sessions/" + s.id))));
    item.appendChild(link);
    if (!s.live) item.appendChild(document.createTextNode(" (stored)"));
    return item;
  }));
}

// ---- drawing -----------------------------------------------------------------------------------

function column(rows, k) { return rows.map((row) => row[k]); }

function pathTrace(rows, name, colour, width) {
  return { type: "scatter3d", mode: "lines", name, x: column(rows, 0), y: column(rows, 1), z: column(rows, 2),
    line: { color: colour, width } };
}

function drawPaths(caseData, proposed) {
  const original = caseData.trajectory;
  const traces = [pathTrace(original, "original", "#1f77b4", 6)];
  if (proposed) traces.push(pathTrace(proposed, "proposed", "#d62728", 5));
  const ends = [original[0], original[original.length - 1]];
  traces.push({ type: "scatter3d", mode: "markers+text", name: "start / goal", x: column(ends, 0),
    y: column(ends, 1), z: column(ends, 2), text: ["start", "goal"], marker: { size: 5, color: "#444" } });
  const objects = caseData.objects || [];
  traces.push({ type: "scatter3d", mode: "markers+text", name: "objects", x: objects.map((o) => o.x),
    y: objects.map((o) => o.y), z: objects.map((o) => o.z), text: objects.map((o) => o.name),
    marker: { size: 6, color: "#ff7f0e" } });
  Plotly.react("plot", traces, { margin: { l: 0, r: 0, t: 20, b: 0 }, legend: { x: 0, y: 1 },
    scene: { xaxis: { title: "x" }, yaxis: { title: "y" }, zaxis: { title: "z" }, aspectmode: "data" } });
  const speed = [{ type: "scatter", mode: "lines", name: "original speed", y: column(original, 3),
    line: { color: "#1f77b4" } }];
  if (proposed) speed.push({ type: "scatter", mode: "lines", name: "proposed speed", y: column(proposed, 3),
    line: { color: "#d62728" } });
  Plotly.react("speed", speed, { margin: { l: 40, r: 10, t: 10, b: 30 },
    xaxis: { title: "waypoint" }, yaxis: { title: "speed" } });
}

// ---- code highlighting (no CDN: a small Python tokenizer) ---------------------------------------

const KEYWORDS = new Set(["def", "return", "for", "in", "if", "else", "elif", "while", "import", "from", "as",
  "and", "or", "not", "None", "True", "False", "lambda", "with", "range", "len"]);

function escapeHtml(text) {
  return text.replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;");
}

function highlight(code) {
  const pattern = /(#[^\n]*)|('(?:[^'\\\n]|\\.)*'|"(?:[^"\\\n]|\\.)*")|\b(\d+(?:\.\d+)?)\b|\b([A-Za-z_]\w*)(?=\s*\()|\b([A-Za-z_]\w*)\b/g;
  let out = "", last = 0, match;
  while ((match = pattern.exec(code)) !== null) {
    out += escapeHtml(code.slice(last, match.index));
    const [text, comment, string, number, call, word] = match;
    if (comment) out += '<span class="com">' + escapeHtml(comment) + "</span>";
    else if (string) out += '<span class="str">' + escapeHtml(string) + "</span>";
    else if (number) out += '<span class="num">' + number + "</span>";
    else if (call) out += '<span class="' + (KEYWORDS.has(call) ? "kw" : "fn") + '">' + call + "</span>";
    else out += KEYWORDS.has(word) ? '<span class="kw">' + word + "</span>" : escapeHtml(text);
    last = match.index + text.length;
  }
  return out + escapeHtml(code.slice(last));
}

guarded(async () => { await loadCaseList(); await loadSessions(); });
