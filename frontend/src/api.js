// The one fetch wrapper: JSON bodies, the CSRF token on every POST, errors shown to the user.
import { clearError, showError } from './toast.js';

let csrf = null;
let onUnauthorized = () => {};

export function setCsrf(token) { csrf = token; window.__sdCsrf = token; }
export function whenUnauthorized(handler) { onUnauthorized = handler; }

export class ApiError extends Error {
  constructor(status, body) {
    super(body && body.error ? body.error : `HTTP ${status}`);
    this.status = status;
    this.quota = body && body.quota;  // "disk" or "runs": a refusal past the account's quota
    this.body = body || {};
  }
}

/// api('/api/x') GETs; api('/api/x', {body}) POSTs. `quiet` leaves the error display to the caller.
export async function api(path, { method, body, quiet = false } = {}) {
  const verb = method || (body === undefined ? 'GET' : 'POST');
  const headers = { Accept: 'application/json' };
  if (verb !== 'GET') {
    headers['Content-Type'] = 'application/json';
    if (csrf) headers['X-CSRF-Token'] = csrf;
  }
  let response;
  try {
    response = await fetch(path, {
      method: verb, headers, credentials: 'same-origin',
      body: verb === 'GET' ? undefined : JSON.stringify(body ?? {}),
    });
  } catch (e) {
    const error = new ApiError(0, { error: `the server does not answer (${e.message})` });
    if (!quiet) showError(error.message);
    throw error;
  }
  const text = await response.text();
  let data = null;
  try { data = text ? JSON.parse(text) : null; } catch { data = { error: text.slice(0, 200) }; }
  if (!response.ok) {
    const error = new ApiError(response.status, data);
    if (response.status === 401 && path !== '/api/sign-in') onUnauthorized();
    else if (!quiet) showError(error.message);
    throw error;
  }
  if (verb !== 'GET' && !quiet) clearError();  // an action that worked: an earlier error is stale
  return data;
}
