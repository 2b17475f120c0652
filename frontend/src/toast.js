// A transient error banner: the app keeps working after any failed request.
let timer = null;

export function showError(message) {
  const el = document.getElementById('toast');
  if (!el) return;
  el.textContent = message;
  el.hidden = false;
  clearTimeout(timer);
  timer = setTimeout(() => { el.hidden = true; }, 6000);
}

/// An error shown for an earlier request is stale once the user moves on (another tab, a request
/// that succeeded): it goes, so that it is never read as this action's outcome.
export function clearError() {
  const el = document.getElementById('toast');
  if (!el) return;
  clearTimeout(timer);
  el.hidden = true;
}
