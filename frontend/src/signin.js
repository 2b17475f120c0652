// The sign-in page: name + password → POST /api/sign-in; the server sets the session cookie.
import { api, setCsrf } from './api.js';

export function showSignIn(onSignedIn) {
  document.getElementById('app').hidden = true;
  const page = document.getElementById('signin');
  page.hidden = false;
  const form = document.getElementById('signin-form');
  const error = document.getElementById('signin-error');
  form.onsubmit = async (e) => {
    e.preventDefault();
    error.hidden = true;
    try {
      const answer = await api('/api/sign-in', {
        body: { name: document.getElementById('signin-name').value.trim(), password: document.getElementById('signin-password').value },
        quiet: true,
      });
      setCsrf(answer.csrf);
      document.getElementById('signin-password').value = '';
      page.hidden = true;
      onSignedIn(answer.user);
    } catch (err) {
      error.textContent = err.status === 401 ? 'Wrong name or password.' : err.message;
      error.hidden = false;
    }
  };
  document.getElementById('signin-name').focus();
}
