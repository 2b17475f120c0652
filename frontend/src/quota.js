// The signed-in account's quota (issue #56), one line in the top bar: the disk its folder uses
// of its limit, and the simulation runs of work started today (UTC) of its per-day limit, as GET
// /api/quota says; read again when a tab is shown and after work that writes or runs. A write the
// quota refuses (HTTP 409, "disk quota: …" or "runs quota: …") is shown as the one-line error
// toast, also by the forms that otherwise keep their errors beside themselves.
import { api } from './api.js';
import { bytesText, countText } from './numbers.js';
import { el } from './properties.js';
import { showError } from './toast.js';

let line = null;
let asked = 0;  // the last reading asked for: older answers are dropped

/// "1.2 MB of 100.0 MB", "1.2 MB, no limit" (null: no limit).
export function useText(used, limit, format) {
  return limit === null || limit === undefined ? `${format(used)}, no limit` : `${format(used)} of ${format(limit)}`;
}

/// "Disk 1.2 MB of 100.0 MB · runs today 5,000 of 100,000".
export function quotaText(q) {
  return `Disk ${useText(q.disk_bytes, q.disk_limit, bytesText)} · runs today ${useText(q.runs_today, q.runs_per_day, countText)}`;
}

/// At or over a limit: what the next write or start would be refused for.
export const full = (used, limit) => limit !== null && limit !== undefined && used >= limit;

/// The line, placed before the account's name in the top bar.
export function initQuota() {
  if (line) return;
  line = el('span', { id: 'quota-line', testid: 'quota-line', class: 'quota-line small', hidden: '',
    title: 'Your quota on this server, set by its administrator: the disk your projects use, and the simulation runs '
      + 'of work started today (UTC); a design counts its budget when it starts, an experiment its whole plan.' });
  document.getElementById('user-name').before(line);
}

export async function refreshQuota() {
  if (!line) return;
  const n = ++asked;
  try {
    const q = await api('/api/quota', { quiet: true });
    if (n !== asked) return;
    line.textContent = quotaText(q);
    line.classList.toggle('full', full(q.disk_bytes, q.disk_limit) || full(q.runs_today, q.runs_per_day));
    line.hidden = false;
  } catch (e) {
    if (n === asked && e.status === 404) line.hidden = true;  // a server without quotas
  }
}

/// Was `error` (an ApiError) a quota's refusal?
export const isQuotaRefusal = (error) => !!error && error.status === 409 && Boolean(error.quota);

/// For a form that shows its own errors (quiet requests): a quota's refusal also goes to the
/// toast, and the line is read again. True when it was one.
export function quotaRefused(error) {
  if (!isQuotaRefusal(error)) return false;
  showError(error.message);
  refreshQuota();
  return true;
}
