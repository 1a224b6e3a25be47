"""A self-contained HTML replay page: one file, inline CSS and JavaScript, no network, opens from disk.

``write_html(index, out_path, episodes)`` embeds the chosen episodes (parsed by ``EpisodeView``) as
one JSON document inside ``<script type="application/json">`` and a small script draws them: the
glyph grid coloured by glyph class, legend, HUD, message, the model's reply, the parsed action or
forfeit reason, reward and return so far, memory, a timeline of the turns, and an episode list
filtered by task, suite and return. Keys: Left/Right step, Home/End, Space play/pause, N/P next or
previous episode.

Safety: model and task text is data, never markup. In the JSON, ``<``, ``>``, ``&`` and U+2028/2029
are written as ``\\u003c``-style escapes, so no reply can close the script element; the page
builds every element with ``textContent`` (never ``innerHTML``); and a Content-Security-Policy
allows only this page's own script (by nonce), so an injected ``<script>`` or ``onerror`` could
not run even if it reached the document.

Size: every frame of an episode is embedded. By default a page holds at most ``MAX_EPISODES``
episodes (the first ones of the selection, with a note saying so); choose others with the
``--episode``/``--task`` options of ``glyphbench replay``.
"""

from __future__ import annotations

import html
import json
import math
import os
import secrets
from pathlib import Path
from typing import Any, Sequence

from .index import EpisodeIndex
from .view import EpisodeView

MAX_EPISODES = 200

_JSON_ESCAPES = {"<": "\\u003c", ">": "\\u003e", "&": "\\u0026", "\u2028": "\\u2028", "\u2029": "\\u2029"}


def script_json(value: Any) -> str:
    """JSON text that is safe inside a ``<script>`` element (cannot end it or start a comment)."""
    text = json.dumps(value, ensure_ascii=False, separators=(",", ":"), allow_nan=False)
    for raw, escaped in _JSON_ESCAPES.items():
        text = text.replace(raw, escaped)
    return text


def episode_json(view: EpisodeView, prompt: int) -> dict[str, Any]:
    """The page's record of one episode; ``prompt`` indexes the shared system-prompt list."""
    meta = {k: v if isinstance(v, str) else json.dumps(v) for k, v in view.meta.items() if v is not None}
    turns = [t.to_json() for t in view.turns]
    for t in turns:
        t["reward"], t["ret"] = _number(t["reward"]), _number(t["ret"])
    return {"i": view.index, "src": view.source, "task": view.task_id, "suite": view.suite,
            "seed": view.seed, "model": view.model, "ret": _number(view.episode_return), "len": view.length,
            "outcome": view.outcome, "forfeits": view.forfeits, "prompt": prompt, "meta": meta,
            "frames": [f.to_json() for f in view.frames], "turns": turns}


def _number(x: float) -> float | str:
    """A number JSON can hold: NaN and infinities (a broken record) travel as text."""
    return x if math.isfinite(x) else str(x)


def write_html(index: EpisodeIndex, out_path: str | Path, episodes: Sequence[int] | None = None, *,
               limit: int = MAX_EPISODES) -> int:
    """Write the replay page for ``episodes`` (indices into ``index``; default all) to ``out_path``.

    At most ``limit`` episodes are embedded, the first ones of the selection. Returns how many
    were. The file appears complete or not at all (written beside, then renamed)."""
    chosen = list(range(len(index)) if episodes is None else episodes)
    if not chosen:
        raise ValueError("no episode selected for the HTML page")
    for i in chosen:
        if not 0 <= i < len(index):
            raise ValueError(f"episode {i} is out of range: {index.path} has {len(index)} episode(s)")
    shown = chosen[:limit]
    note = ""
    if len(shown) < len(chosen):
        note = (f"Showing the first {len(shown)} of {len(chosen)} selected episodes; "
                f"choose others with --episode or --task.")
    head = {"source": str(index.path), "total": len(index), "selected": len(chosen), "note": note,
            "skipped": len(index.warnings), "firstSkipped": index.warnings[0] if index.warnings else "",
            "suites": sorted({index.entries[i].suite for i in shown})}
    out_path = Path(out_path)
    tmp = out_path.with_name(f".{out_path.name}.tmp")
    nonce = secrets.token_urlsafe(16)
    title = html.escape(f"glyphbench replay: {index.path.name}")
    page_head, page_tail = (part.replace("__NONCE__", nonce).replace("__TITLE__", title)
                            for part in _PAGE.split("__DATA__"))
    try:
        with open(tmp, "w", encoding="utf-8") as fh:
            fh.write(page_head)
            fh.write(script_json(head)[:-1] + ',"episodes":[')
            prompts: dict[str, int] = {}
            for n, view in enumerate(index.view(i) for i in shown):     # one episode in memory at a time
                prompt = prompts.setdefault(view.system_prompt, len(prompts))
                fh.write(("," if n else "") + script_json(episode_json(view, prompt)))
            fh.write('],"prompts":' + script_json(list(prompts)) + "}")
            fh.write(page_tail)
        os.replace(tmp, out_path)
    finally:
        tmp.unlink(missing_ok=True)
    return len(shown)


_CSS = r"""
:root { color-scheme: dark light;
  --bg: #14161a; --panel: #1c1f25; --panel2: #23272e; --line: #2f343d; --text: #dde2e8;
  --muted: #8b939e; --accent: #7aa2f7; --good: #3ecf8e; --bad: #f7768e; --warn: #e0af68;
  --g-agent: #ffd166; --g-hazard: #ff5d73; --g-goal: #3ddc97; --g-item: #5ccfe6; --g-water: #4f8cff;
  --g-wall: #636c7a; --g-empty: #4a515c; --g-other: #d7dbe0;
  --t-red: #ff6b6b; --t-green: #51cf66; --t-blue: #4dabf7; --t-yellow: #ffd43b; --t-purple: #b197fc;
  --t-grey: #adb5bd; --t-orange: #ff922b; }
@media (prefers-color-scheme: light) { :root {
  --bg: #f4f5f7; --panel: #ffffff; --panel2: #f0f2f5; --line: #d9dde3; --text: #1d232b;
  --muted: #5f6b7a; --accent: #3559c7; --good: #1a8f5a; --bad: #c92a4b; --warn: #a86b00;
  --g-agent: #b8860b; --g-hazard: #d42a45; --g-goal: #138a57; --g-item: #0f7f99; --g-water: #2456d6;
  --g-wall: #8f98a5; --g-empty: #b4bac3; --g-other: #1d232b;
  --t-red: #d6336c; --t-green: #2b8a3e; --t-blue: #1971c2; --t-yellow: #b08900; --t-purple: #7048e8;
  --t-grey: #6c757d; --t-orange: #d9480f; } }
* { box-sizing: border-box; }
body { margin: 0; background: var(--bg); color: var(--text);
  font: 14px/1.45 system-ui, -apple-system, "Segoe UI", Roboto, sans-serif; }
.mono, pre, .grid, .hud, kbd { font-family: "DejaVu Sans Mono", Menlo, Consolas, "Liberation Mono", monospace; }
header.top { display: flex; gap: 12px; align-items: baseline; padding: 8px 16px;
  border-bottom: 1px solid var(--line); background: var(--panel); }
header.top b { font-size: 15px; }
header.top .src { color: var(--muted); overflow: hidden; text-overflow: ellipsis; white-space: nowrap; }
.note { color: var(--warn); }
.layout { display: grid; grid-template-columns: 300px minmax(0, 1fr); min-height: calc(100vh - 40px); }
aside { border-right: 1px solid var(--line); background: var(--panel); display: flex; flex-direction: column;
  max-height: calc(100vh - 40px); position: sticky; top: 0; }
.filters { padding: 10px; display: grid; gap: 6px; border-bottom: 1px solid var(--line); }
.filters label, .filters .range { display: grid; grid-template-columns: 52px 1fr; align-items: center; gap: 6px;
  color: var(--muted); }
.filters .range { grid-template-columns: 52px 1fr 1fr; }
input, select, button { font: inherit; color: var(--text); background: var(--panel2);
  border: 1px solid var(--line); border-radius: 6px; padding: 3px 7px; min-width: 0; }
button { cursor: pointer; } button:hover { border-color: var(--accent); }
#count { color: var(--muted); font-size: 12px; }
#episodes { list-style: none; margin: 0; padding: 0; overflow-y: auto; flex: 1; }
#episodes li { padding: 7px 10px; border-bottom: 1px solid var(--line); cursor: pointer; }
#episodes li:hover { background: var(--panel2); }
#episodes li.current { background: var(--panel2); box-shadow: inset 3px 0 var(--accent); }
#episodes .t { font-weight: 600; overflow: hidden; text-overflow: ellipsis; white-space: nowrap; }
#episodes .s { color: var(--muted); font-size: 12px; }
.pos { color: var(--good); } .neg { color: var(--bad); }
main { padding: 14px 18px; min-width: 0; }
h1 { font-size: 18px; margin: 0 0 6px; word-break: break-all; }
.chips { display: flex; flex-wrap: wrap; gap: 6px; margin-bottom: 10px; }
.chip { background: var(--panel2); border: 1px solid var(--line); border-radius: 999px; padding: 1px 9px;
  font-size: 12.5px; }
.chip i { font-style: normal; color: var(--muted); margin-right: 4px; }
.controls { display: flex; flex-wrap: wrap; gap: 6px; align-items: center; margin: 6px 0; }
.controls .sep { width: 10px; }
#step-input { width: 70px; }
.timeline { display: flex; gap: 1px; height: 16px; margin: 6px 0 12px; cursor: pointer; }
.timeline span { flex: 1 1 0; min-width: 1px; background: var(--line); border-radius: 2px; }
.timeline span.rw-pos { background: var(--good); } .timeline span.rw-neg { background: var(--t-purple); }
.timeline span.ch-unchanged { background: var(--warn); } .timeline span.ch-forfeit { background: var(--bad); }
.timeline span.end { background: var(--muted); }
.timeline span.at { outline: 2px solid var(--text); outline-offset: 1px; }
.panes { display: grid; grid-template-columns: minmax(0, 1.1fr) minmax(0, 1fr); gap: 14px; align-items: start; }
@media (max-width: 1100px) { .panes { grid-template-columns: 1fr; }
  .layout { grid-template-columns: 240px 1fr; } }
.panel { background: var(--panel); border: 1px solid var(--line); border-radius: 10px; padding: 12px 14px; }
.board.stale { border: 2px dashed var(--warn); }
.board.forfeit { border: 2px dashed var(--bad); }
.hud { color: var(--muted); margin-bottom: 8px; white-space: pre-wrap; }
.grid { line-height: 1.08; white-space: pre; display: inline-block; padding: 8px 10px; border-radius: 6px;
  background: var(--bg); letter-spacing: 0; font-variant-ligatures: none; }
.grid .row { height: 1.08em; }
.axis { color: var(--muted); }
.g-agent { color: var(--g-agent); font-weight: 700; } .g-hazard { color: var(--g-hazard); font-weight: 700; }
.g-goal { color: var(--g-goal); font-weight: 700; } .g-item { color: var(--g-item); }
.g-water { color: var(--g-water); } .g-wall { color: var(--g-wall); } .g-empty { color: var(--g-empty); }
.g-other { color: var(--g-other); }
.t-red { color: var(--t-red); } .t-green { color: var(--t-green); } .t-blue { color: var(--t-blue); }
.t-yellow { color: var(--t-yellow); } .t-purple { color: var(--t-purple); } .t-grey { color: var(--t-grey); }
.t-orange { color: var(--t-orange); }
.legend { display: flex; flex-wrap: wrap; gap: 4px 14px; margin-top: 10px; font-size: 13px; }
.legend .glyph { font-family: "DejaVu Sans Mono", Menlo, Consolas, monospace; font-size: 16px;
  margin-right: 5px; }
.legend-note { color: var(--muted); font-size: 12px; margin-top: 6px; }
.message { margin-top: 10px; padding: 6px 10px; border-left: 3px solid var(--accent); background: var(--panel2);
  white-space: pre-wrap; }
.turn-head { display: flex; flex-wrap: wrap; gap: 8px; align-items: center; margin-bottom: 8px; }
.turn-head .n { font-weight: 700; font-size: 16px; }
.badge { border-radius: 5px; padding: 1px 8px; font-size: 12.5px; font-weight: 600; }
.badge.action { background: color-mix(in srgb, var(--accent) 20%, transparent); color: var(--accent); }
.badge.forfeit { background: color-mix(in srgb, var(--bad) 20%, transparent); color: var(--bad); }
.badge.unchanged { background: color-mix(in srgb, var(--warn) 20%, transparent); color: var(--warn); }
.badge.length { background: color-mix(in srgb, var(--t-purple) 20%, transparent); color: var(--t-purple); }
.badge.end { background: var(--panel2); color: var(--text); }
.reason { color: var(--bad); margin-bottom: 8px; white-space: pre-wrap; }
.numbers { display: flex; gap: 16px; margin-bottom: 8px; }
.numbers i { font-style: normal; color: var(--muted); margin-right: 4px; }
h3 { font-size: 12px; text-transform: uppercase; letter-spacing: .06em; color: var(--muted);
  margin: 10px 0 4px; }
pre.text { white-space: pre-wrap; word-break: break-word; margin: 0; padding: 8px 10px; background: var(--bg);
  border-radius: 6px; max-height: 46vh; overflow: auto; font-size: 12.5px; }
pre .think { color: var(--muted); } pre .act { color: var(--accent); font-weight: 700; }
details { margin-top: 10px; } summary { cursor: pointer; color: var(--muted); }
.empty-note { color: var(--muted); font-style: italic; }
footer { color: var(--muted); font-size: 12px; margin-top: 14px; }
kbd { border: 1px solid var(--line); border-bottom-width: 2px; border-radius: 4px; padding: 0 4px;
  font-size: 11px; }
"""

_JS = r"""
"use strict";
(function () {
  const DATA = JSON.parse(document.getElementById("replay-data").textContent);
  const $ = (id) => document.getElementById(id);
  const state = { ep: null, pos: 0, timer: null, visible: [] };

  function el(tag, cls, text) {
    const node = document.createElement(tag);
    if (cls) node.className = cls;
    if (text !== undefined && text !== null) node.textContent = String(text);
    return node;
  }
  function signed(x) { return (x < 0 ? "\u2212" : "+") + Math.abs(x).toFixed(3); }
  function signClass(x) { return x > 0 ? "pos" : x < 0 ? "neg" : ""; }
  function chip(label, value, cls) {
    const c = el("span", "chip");
    c.appendChild(el("i", null, label));
    c.appendChild(el("span", cls || null, value));
    return c;
  }
  function shortTask(id) { return id.replace(/^glyphbench\//, ""); }

  // ---- episode list and filters ------------------------------------------------------------
  function globRegex(text) {
    const body = text.replace(/[.+^${}()|[\]\\]/g, "\\$&").replace(/\*/g, ".*").replace(/\?/g, ".");
    return new RegExp("^" + body + "$", "i");
  }
  function matches(ep) {
    const task = $("f-task").value.trim();
    if (task) {
      if (/[*?]/.test(task)) { if (!globRegex(task).test(ep.task)) return false; }
      else if (!ep.task.toLowerCase().includes(task.toLowerCase())) return false;
    }
    const suite = $("f-suite").value;
    if (suite && ep.suite !== suite) return false;
    const lo = parseFloat($("f-min").value), hi = parseFloat($("f-max").value);
    if (!Number.isNaN(lo) && ep.ret < lo) return false;
    if (!Number.isNaN(hi) && ep.ret > hi) return false;
    return true;
  }
  function buildList() {
    const list = $("episodes");
    DATA.episodes.forEach((ep, k) => {
      const li = el("li");
      li.dataset.k = String(k);
      li.appendChild(el("div", "t", shortTask(ep.task)));
      const s = el("div", "s");
      s.appendChild(document.createTextNode("#" + ep.i + " \u00b7 seed " + ep.seed + " \u00b7 "));
      s.appendChild(el("span", signClass(ep.ret), signed(ep.ret)));
      s.appendChild(document.createTextNode(" \u00b7 " + ep.len + " turns \u00b7 " + ep.outcome));
      li.appendChild(s);
      li.addEventListener("click", () => openEpisode(k));
      list.appendChild(li);
    });
    const tasks = [...new Set(DATA.episodes.map((e) => e.task))].sort();
    tasks.forEach((t) => { const o = el("option"); o.value = t; $("task-names").appendChild(o); });
    DATA.suites.forEach((s) => { const o = el("option", null, s); o.value = s; $("f-suite").appendChild(o); });
    ["f-task", "f-suite", "f-min", "f-max"].forEach((id) => $(id).addEventListener("input", applyFilter));
  }
  function applyFilter() {
    state.visible = [];
    document.querySelectorAll("#episodes li").forEach((li) => {
      const k = Number(li.dataset.k);
      const show = matches(DATA.episodes[k]);
      li.hidden = !show;
      if (show) state.visible.push(k);
    });
    $("count").textContent = state.visible.length + " of " + DATA.episodes.length + " episodes shown";
  }
  function stepEpisode(delta) {
    if (!state.visible.length) return;
    const at = state.visible.indexOf(state.k);
    const next = at < 0 ? 0 : Math.min(state.visible.length - 1, Math.max(0, at + delta));
    openEpisode(state.visible[next]);
  }

  // ---- one episode ----------------------------------------------------------------------------
  function openEpisode(k) {
    stop();
    state.k = k;
    state.ep = DATA.episodes[k];
    document.querySelectorAll("#episodes li").forEach(
      (li) => li.classList.toggle("current", Number(li.dataset.k) === k));
    const ep = state.ep;
    $("ep-title").textContent = ep.task;
    const chips = $("ep-chips");
    chips.replaceChildren(
      chip("suite", ep.suite), chip("seed", ep.seed), chip("model", ep.model),
      chip("return", signed(ep.ret), signClass(ep.ret)), chip("outcome", ep.outcome),
      chip("turns", ep.len), chip("forfeits", ep.forfeits), chip("episode", "#" + ep.i + "  " + ep.src));
    const meta = $("meta-list");
    meta.replaceChildren();
    Object.keys(ep.meta).forEach((key) => meta.appendChild(chip(key, ep.meta[key])));
    $("system-prompt").textContent = DATA.prompts[ep.prompt] || "(no system prompt recorded)";
    const line = $("timeline");
    line.replaceChildren();
    for (let p = 0; p <= ep.len; p++) {
      const t = ep.turns[p];
      const tick = el("span", tickClass(t));
      tick.title = t ? "step " + p + ": " + (t.action || "forfeit") + " " + signed(t.reward)
        + (t.change === "unchanged" ? " (no change)" : "") : "final observation";
      tick.addEventListener("click", () => go(p));
      line.appendChild(tick);
    }
    $("step-input").max = String(ep.len);
    $("step-total").textContent = "/ " + ep.len;
    go(0);
  }

  function tickClass(t) {
    if (!t) return "end";
    if (t.change) return "ch-" + t.change;
    return t.reward > 0 ? "rw-pos" : t.reward < 0 ? "rw-neg" : "";
  }

  function go(p) {
    const ep = state.ep;
    if (!ep) return;
    state.pos = Math.max(0, Math.min(ep.len, p));
    $("step-input").value = String(state.pos);
    document.querySelectorAll("#timeline span").forEach((s, i) => s.classList.toggle("at", i === state.pos));
    drawFrame(ep.frames[state.pos]);
    drawTurn(ep, state.pos);
    if (state.pos >= ep.len) stop();
  }

  function drawFrame(frame) {
    $("hud").textContent = frame.hud;
    const grid = $("grid");
    grid.replaceChildren();
    if (!frame.grid.length) { grid.appendChild(el("span", "empty-note", "(no observation recorded)")); }
    const byGlyph = new Map(frame.legend.map((e) => [e[0], e]));
    const rows = frame.grid.map((r) => Array.from(r));
    const cols = rows.reduce((m, r) => Math.max(m, r.length), 0);
    const width = String(rows.length).length;
    frame.above.forEach((line) => grid.appendChild(el("div", "row axis", line)));
    if (frame.axes) {
      let letters = " ".repeat(width + 1);
      for (let c = 0; c < cols; c++) letters += String.fromCharCode(65 + c);
      grid.appendChild(el("div", "row axis", letters));
    }
    rows.forEach((cells, r) => {
      const row = el("div", "row");
      if (frame.axes) row.appendChild(el("span", "axis", String(r + 1).padStart(width) + " "));
      let run = "", runClass = null;
      for (const ch of cells) {
        const e = byGlyph.get(ch);
        const cls = e ? "g-" + e[2] + (e[3] ? " t-" + e[3] : "") : "g-other";
        if (cls !== runClass && run) { row.appendChild(el("span", runClass, run)); run = ""; }
        runClass = cls;
        run += ch;
      }
      if (run) row.appendChild(el("span", runClass, run));
      if (frame.beside[r]) row.appendChild(el("span", "axis", " " + frame.beside[r]));
      grid.appendChild(row);
    });
    const notes = frame.beside.reduce((m, n) => Math.max(m, n ? n.length + 1 : 0), 0);
    const wide = Math.max(cols + (frame.axes ? width + 1 : 0) + notes,
                          ...frame.above.map((line) => line.length));
    const room = $("board").clientWidth - 50;
    const byWidth = room / Math.max(1, wide) / 0.61;
    const byHeight = (window.innerHeight * 0.62) / Math.max(1, rows.length + 1 + frame.above.length) / 1.08;
    const size = Math.floor(Math.min(byWidth, byHeight));
    grid.style.fontSize = Math.max(10, Math.min(96, size)) + "px";   // small boards fill the panel
    const legend = $("legend");
    legend.replaceChildren();
    frame.legend.forEach((e) => {
      const item = el("span");
      item.appendChild(el("span", "glyph g-" + e[2] + (e[3] ? " t-" + e[3] : ""), e[0]));
      item.appendChild(document.createTextNode(e[1]));
      legend.appendChild(item);
    });
    $("legend-note").hidden = !frame.legendCarried;
    $("message").hidden = !frame.message;
    $("message").textContent = frame.message;
  }

  function replyNodes(text) {
    // reasoning dimmed, the action tag highlighted; every piece is a text node
    const pre = $("reply");
    pre.replaceChildren();
    if (!text) { pre.appendChild(el("span", "empty-note", "(empty reply)")); return; }
    const re = /<think>[\s\S]*?(<\/think>|$)|<action>[\s\S]*?<\/action>/g;
    let last = 0, m;
    while ((m = re.exec(text)) !== null) {
      if (m.index > last) pre.appendChild(document.createTextNode(text.slice(last, m.index)));
      pre.appendChild(el("span", m[0].startsWith("<think>") ? "think" : "act", m[0]));
      last = m.index + m[0].length;
      if (!m[0].length) re.lastIndex++;
    }
    if (last < text.length) pre.appendChild(document.createTextNode(text.slice(last)));
  }

  function drawTurn(ep, p) {
    const head = $("turn-head");
    head.replaceChildren();
    const t = ep.turns[p];
    const board = $("board");
    board.classList.toggle("stale", !!t && t.change === "unchanged");
    board.classList.toggle("forfeit", !!t && t.change === "forfeit");
    $("turn-body").hidden = !t;
    if (!t) {
      head.appendChild(el("span", "n", "Episode over"));
      head.appendChild(el("span", "badge end", ep.outcome + " after " + ep.len + " turns"));
      head.appendChild(el("span", "badge end " + signClass(ep.ret), "return " + signed(ep.ret)));
      $("reason").hidden = true;
      return;
    }
    head.appendChild(el("span", "n", "Turn " + t.turn));
    if (t.action !== null) head.appendChild(el("span", "badge action", "action " + t.action));
    else head.appendChild(el("span", "badge forfeit", "forfeit"));
    if (t.change === "unchanged") head.appendChild(el("span", "badge unchanged", "no change"));
    if (t.change === "forfeit") head.appendChild(el("span", "badge unchanged", "world unchanged"));
    if (t.finish === "length") head.appendChild(el("span", "badge length", "reply cut at token limit"));
    $("reason").hidden = t.action !== null;
    $("reason").textContent = t.forfeit ? "Forfeit: " + t.forfeit : "Forfeit";
    $("reward").textContent = signed(t.reward);
    $("reward").className = signClass(t.reward);
    $("ret").textContent = signed(t.ret);
    $("ret").className = signClass(t.ret);
    replyNodes(t.reply);
    $("memory-box").hidden = t.memory === null;
    $("memory").textContent = t.memory || "";
  }

  // ---- playback and keys ----------------------------------------------------------------------
  function stop() {
    if (state.timer !== null) clearInterval(state.timer);
    state.timer = null;
    $("play").textContent = "\u25b6 Play";
  }
  function play() {
    if (!state.ep) return;
    if (state.pos >= state.ep.len) go(0);
    const rate = parseFloat($("speed").value);
    state.timer = setInterval(() => go(state.pos + 1), 1000 / rate);
    $("play").textContent = "\u275a\u275a Pause";
  }
  function toggle() { if (state.timer === null) play(); else stop(); }

  $("first").addEventListener("click", () => go(0));
  $("prev").addEventListener("click", () => go(state.pos - 1));
  $("play").addEventListener("click", toggle);
  $("next").addEventListener("click", () => go(state.pos + 1));
  $("last").addEventListener("click", () => go(state.ep ? state.ep.len : 0));
  $("prev-ep").addEventListener("click", () => stepEpisode(-1));
  $("next-ep").addEventListener("click", () => stepEpisode(1));
  $("speed").addEventListener("change", () => { if (state.timer !== null) { stop(); play(); } });
  $("step-input").addEventListener("change", () => {
    const v = parseInt($("step-input").value, 10);
    if (!Number.isNaN(v)) go(v);
  });
  document.addEventListener("keydown", (e) => {
    const tag = e.target && e.target.tagName;
    if (tag === "INPUT" || tag === "SELECT" || tag === "TEXTAREA" || e.ctrlKey || e.metaKey || e.altKey) return;
    const actions = {
      ArrowRight: () => go(state.pos + 1), ArrowLeft: () => go(state.pos - 1),
      Home: () => go(0), End: () => go(state.ep ? state.ep.len : 0), " ": toggle,
      n: () => stepEpisode(1), p: () => stepEpisode(-1), N: () => stepEpisode(1), P: () => stepEpisode(-1),
    };
    const action = actions[e.key];
    if (!action) return;
    e.preventDefault();
    if (tag === "BUTTON") e.target.blur();     // so Space does not also click the focused button
    action();
  });
  window.addEventListener("resize", () => { if (state.ep) go(state.pos); });

  $("source").textContent = DATA.source + " \u00b7 " + DATA.total + " episode(s) in the file";
  const skipped = DATA.skipped ? DATA.skipped + " unreadable line(s) skipped, the first: " + DATA.firstSkipped : "";
  $("note").textContent = [DATA.note, skipped].filter(Boolean).join("  ");
  buildList();
  applyFilter();
  if (DATA.episodes.length) openEpisode(0);
})();
"""

_BODY = r"""
<header class="top"><b>glyphbench replay</b><span class="src" id="source"></span>
  <span class="note" id="note"></span></header>
<div class="layout">
<aside>
  <div class="filters">
    <label>task <input id="f-task" list="task-names" placeholder="substring or glob"></label>
    <datalist id="task-names"></datalist>
    <label>suite <select id="f-suite"><option value="">all suites</option></select></label>
    <div class="range">return <input id="f-min" type="number" step="0.05" placeholder="min">
      <input id="f-max" type="number" step="0.05" placeholder="max"></div>
    <div id="count"></div>
  </div>
  <ol id="episodes"></ol>
</aside>
<main>
  <h1 id="ep-title"></h1>
  <div class="chips" id="ep-chips"></div>
  <div class="controls">
    <button id="prev-ep" title="previous episode (P)">&#8676; Episode</button>
    <button id="next-ep" title="next episode (N)">Episode &#8677;</button>
    <span class="sep"></span>
    <button id="first" title="first step (Home)">|&#9664;</button>
    <button id="prev" title="previous step (Left)">&#9664;</button>
    <button id="play" title="play / pause (Space)">&#9654; Play</button>
    <button id="next" title="next step (Right)">&#9654;</button>
    <button id="last" title="final observation (End)">&#9654;|</button>
    <span class="sep"></span>
    <label>step <input id="step-input" type="number" min="0" value="0"></label><span id="step-total"></span>
    <span class="sep"></span>
    <label>speed <select id="speed">
      <option value="0.5">0.5 /s</option><option value="1">1 /s</option><option value="2" selected>2 /s</option>
      <option value="4">4 /s</option><option value="8">8 /s</option><option value="16">16 /s</option>
    </select></label>
  </div>
  <div class="timeline" id="timeline" title="turns: green reward, purple penalty, amber no change, red forfeit"></div>
  <div class="panes">
    <section class="panel board" id="board">
      <div class="hud" id="hud"></div>
      <div class="grid" id="grid"></div>
      <div class="legend" id="legend"></div>
      <div class="legend-note" id="legend-note" hidden>legend left out of this observation;
        named from earlier steps</div>
      <div class="message" id="message" hidden></div>
    </section>
    <section class="panel">
      <div class="turn-head" id="turn-head"></div>
      <div class="reason" id="reason" hidden></div>
      <div id="turn-body">
        <div class="numbers"><span><i>reward</i><b id="reward"></b></span>
          <span><i>return so far</i><b id="ret"></b></span></div>
        <h3>Reply</h3>
        <pre class="text" id="reply"></pre>
        <div id="memory-box" hidden><h3>Memory</h3><pre class="text" id="memory"></pre></div>
      </div>
      <details><summary>System prompt</summary><pre class="text" id="system-prompt"></pre></details>
      <details><summary>Run metadata</summary><div class="chips" id="meta-list"></div></details>
    </section>
  </div>
  <footer><kbd>&larr;</kbd> <kbd>&rarr;</kbd> step &middot; <kbd>Home</kbd> <kbd>End</kbd> first / final
    &middot; <kbd>Space</kbd> play / pause &middot; <kbd>N</kbd> <kbd>P</kbd> next / previous episode.
    The grid shows the world before the turn's action; the last step is the final observation.
    Colours mark glyph classes for reading only; the model saw plain text.</footer>
</main>
</div>
"""

_PAGE = ("<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
         "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
         "style-src 'unsafe-inline'; script-src 'nonce-__NONCE__'; img-src data:\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<title>__TITLE__</title>\n<style>" + _CSS + "</style></head>\n<body>" + _BODY
         + "<script type=\"application/json\" id=\"replay-data\">__DATA__</script>\n"
         + "<script nonce=\"__NONCE__\">" + _JS + "</script>\n</body></html>\n")
