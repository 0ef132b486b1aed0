// Talking to the service (docs/api.md) and telling the user what went wrong. Every request goes
// through authorizedFetch, which adds the API token when one is set (token.js).
import { tokenRefused, withToken } from "./token.js";

export const $ = (id) => document.getElementById(id);

export function showMessage(text, kind = "error") {
  const box = $("message");
  box.textContent = text;
  box.className = kind === "error" ? "message" : "message info";
  box.hidden = false;
}

export function clearMessage() { $("message").hidden = true; }

// fetch() with the API token; a 401 is also shown next to the token field. A busy service answers
// 429 with Retry-After (its heavy-work pool or this client's share of it is full, as when a lens's
// diagram, analysis and ghosts for several settings are on their way): asked again after that wait,
// for up to a minute, so that a save or upload clicked while the page's own work fills its share
// waits its turn instead of failing.
const BUSY_PATIENCE_S = 60;
export async function authorizedFetch(path, options = {}) {
  for (let waited = 0; ; ) {
    const response = await fetch(path, { ...options, headers: withToken(options.headers) });
    if (response.status === 401) tokenRefused();
    if (response.status !== 429 || waited >= BUSY_PATIENCE_S) return response;
    const seconds = Math.min(Math.max(Number(response.headers.get("Retry-After")) || 1, 0.1), 10);
    await new Promise((resolve) => setTimeout(resolve, seconds * 1000));
    waited += seconds;
  }
}

// Fetches JSON; throws an Error carrying the service's {"error"} text (and .status, .body) or a description.
export async function api(path, options = {}) {
  let response;
  try {
    response = await authorizedFetch(path, options);
  } catch (e) {
    throw new Error("The lenslab service cannot be reached (" + e.message + "). Is it still running?");
  }
  const text = await response.text();
  let body = null;
  try { body = text ? JSON.parse(text) : null; } catch (e) { body = null; }
  if (!response.ok) {
    const error = new Error(body && body.error ? body.error : response.status + " " + response.statusText);
    error.status = response.status;
    error.body = body;
    throw error;
  }
  return body;
}

// Uploads a file as the multipart field "file" (the service's upload routes); `kind` names what it is
// in the refusal ("lens tables"). Throws an Error past the service's default --max-body, 1 MiB.
export function uploadFile(path, file, kind) {
  if (file.size > 1024 * 1024) throw new Error(`"${file.name}" is ${Math.round(file.size / 1024)} KiB; ${kind} are at most 1 MiB`);
  const form = new FormData();
  form.append("file", file, file.name);
  return api(path, { method: "POST", body: form });
}

export const postJson = (path, body) =>
  api(path, { method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body) });

export const fixed = (v, digits = 3) => (v === null || v === undefined || !isFinite(v)) ? "–" : Number(v).toFixed(digits);

// "about 12 s left" from elapsed time and the fraction done; "" when it cannot be told yet.
export function etaText(etaSeconds) {
  if (etaSeconds === null || etaSeconds === undefined || !isFinite(etaSeconds)) return "";
  return etaSeconds < 90 ? `about ${Math.ceil(etaSeconds)} s left` : `about ${Math.ceil(etaSeconds / 60)} min left`;
}

// Browsers open at most 6 connections to one HTTP/1.1 host and an event stream holds one for its
// whole life: beyond this many streams, jobs are polled so that requests are never starved.
const MAX_STREAMS = 3;
let openStreams = 0;

// Follows a job through server-sent events; when the stream breaks before the job is over (or too
// many are open), polls instead. onUpdate(status) returns true once the job is over.
export function follow(eventsUrl, pollUrl, onUpdate, pollEvery = 500) {
  let over = false;
  const poll = async () => {
    while (!over) {
      try {
        over = await onUpdate(await api(pollUrl()));
      } catch (e) {
        if (e.status === 404) return;
      }
      if (!over) await new Promise((r) => setTimeout(r, pollEvery));
    }
  };
  if (!window.EventSource || openStreams >= MAX_STREAMS) { poll(); return; }
  const source = new EventSource(eventsUrl);
  openStreams++;
  let closed = false;
  const close = () => {
    if (closed) return;
    closed = true;
    source.close();
    openStreams--;
  };
  let queue = Promise.resolve();
  source.onmessage = (event) => {
    const status = JSON.parse(event.data);
    queue = queue.then(async () => {
      if (over) return;
      over = await onUpdate(status);
      if (over) close();
    });
  };
  source.onerror = () => {
    close();
    queue.then(() => { if (!over) poll(); });
  };
}
