// The report build from the page's header: start it, follow its progress (server-sent events,
// polling as the fallback) with an estimate of the time left.
import { $, api, etaText, follow, showMessage } from "./api.js";

function reportEta(job) {
  const p = job.progress || {};
  if (!job.started || !p.done || !p.total) return "";
  const elapsed = Date.now() / 1000 - job.started;
  return elapsed > 0 ? etaText((elapsed / p.done) * (p.total - p.done)) : "";
}

function showReportStatus(job) {
  const p = job.progress || {};
  const eta = job.state === "running" ? reportEta(job) : "";
  $("report-status").textContent = {
    idle: "",
    running: `building the report: ${p.done || 0} of ${p.total || "?"} items${eta ? ", " + eta : ""}`,
    done: job.summary ? `report built: ${job.summary.built} items made, ${job.summary.reused} reused` : "report built",
    failed: "the report failed: " + (job.error || "unknown error"),
    cancelled: "the report build was cancelled",
  }[job.state] || "";
  const progress = $("report-progress");
  progress.hidden = job.state !== "running";
  progress.value = p.total ? p.done / p.total : 0;
  $("report-build").disabled = job.state === "running";
  return job.state !== "running";
}

export function followReport() {
  follow("/api/report/events", () => "/api/report", showReportStatus, 1000);
}

async function buildReport() {
  try {
    showReportStatus(await api("/api/report", { method: "POST" }));
    followReport();
  } catch (e) {
    showMessage("The report could not be started: " + e.message);
  }
}

export function setUpReport() { $("report-build").addEventListener("click", buildReport); }
