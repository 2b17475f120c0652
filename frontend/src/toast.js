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
