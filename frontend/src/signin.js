// The sign-in page: name + password → POST /api/sign-in; the server sets the session cookie.
// Beside it, sign-up by the server's policy (GET /api/sign-up, `run-exp --sign-up`): none when
// closed (the default: accounts are made at the server's terminal), by an administrator's
// invitation, or open. A link `#invite=CODE` opens the sign-up form with the code filled in (and
// the code leaves the address bar). A new account is signed in as by a sign-in.
import { api, setCsrf } from './api.js';
import { showError as showToast } from './toast.js';

const $ = (id) => document.getElementById(id);
let useInvitation = null;  // the sign-in page's: opens the sign-up form with a code
let pending = null;        // a code pasted before the policy was known

// A link pasted into a page already open changes the hash only (no reload).
window.addEventListener('hashchange', () => {
  if (!location.hash.startsWith('#invite=')) return;
  const code = takeInvitationFromAddress();
  if (!$('signin').hidden) { if (useInvitation) useInvitation(code); else pending = code; }
  else if (!$('app').hidden)
    showToast(`You are signed in as ${$('user-name').textContent}: to sign up with this invitation, sign out and open its link again.`);
});

/// The server's sign-up policy: closed, invite or open ("closed" for a server that has none).
async function signUpPolicy() {
  try {
    const answer = await api('/api/sign-up', { quiet: true });
    return ['invite', 'open'].includes(answer && answer.policy) ? answer.policy : 'closed';
  } catch {
    return 'closed';
  }
}

/// The code of an invitation link (#invite=CODE), taken out of the address bar; null without one.
function takeInvitationFromAddress() {
  const match = /^#invite=([^&]*)/.exec(location.hash);
  if (!match) return null;
  if (history.replaceState) history.replaceState(null, '', location.pathname + location.search);
  else location.hash = '';
  try { return decodeURIComponent(match[1]).trim(); } catch { return match[1].trim(); }
}

function showError(element, message) {
  element.textContent = message.split('\n')[0];  // one line, as the server writes them
  element.hidden = false;
}

export function showSignIn(onSignedIn) {
  document.getElementById('app').hidden = true;
  const page = $('signin');
  page.hidden = false;
  const form = $('signin-form');
  const error = $('signin-error');
  const upForm = $('signup-form');
  const upError = $('signup-error');

  const signedIn = (answer) => {
    setCsrf(answer.csrf);
    for (const id of ['signin-password', 'signup-password', 'signup-again', 'signup-invitation']) $(id).value = '';
    page.hidden = true;
    onSignedIn(answer.user);
  };
  const showForm = (signUp) => {
    form.hidden = signUp;
    upForm.hidden = !signUp;
    error.hidden = true;
    upError.hidden = true;
    $(signUp ? (upForm.dataset.policy === 'invite' && !$('signup-invitation').value ? 'signup-invitation' : 'signup-name') : 'signin-name').focus();
  };

  form.onsubmit = async (e) => {
    e.preventDefault();
    error.hidden = true;
    try {
      signedIn(await api('/api/sign-in', {
        body: { name: $('signin-name').value.trim(), password: $('signin-password').value },
        quiet: true,
      }));
    } catch (err) {
      showError(error, err.status === 401 ? 'Wrong name or password.' : err.message);
    }
  };
  upForm.onsubmit = async (e) => {
    e.preventDefault();
    upError.hidden = true;
    const password = $('signup-password').value;
    if (password !== $('signup-again').value) {
      showError(upError, 'The two passwords differ.');
      return;
    }
    const body = { name: $('signup-name').value.trim(), password };
    if (upForm.dataset.policy === 'invite') body.invitation = $('signup-invitation').value.trim();
    try {
      signedIn(await api('/api/sign-up', { body, quiet: true }));
    } catch (err) {
      showError(upError, err.message);
    }
  };
  upForm.oninput = () => { upError.hidden = true; };  // what it said is about what was there before
  $('signin-show-signup').onclick = () => showForm(true);
  $('signup-show-signin').onclick = () => showForm(false);

  showForm(false);
  const taken = takeInvitationFromAddress();
  if (taken !== null) pending = taken;
  delete page.dataset.signUp;
  useInvitation = null;
  signUpPolicy().then((policy) => {
    page.dataset.signUp = policy;  // for the tests: the policy is known
    upForm.dataset.policy = policy;
    $('signin-to-signup').hidden = policy === 'closed';
    $('signup-invitation-label').hidden = policy !== 'invite';
    $('signup-invitation').required = policy === 'invite';
    $('signup-intro').textContent = policy === 'invite'
      ? 'Make your account on this server with the invitation code its administrator gave you.'
      : 'Make your account on this server.';
    useInvitation = (code) => {
      if (policy === 'closed') {
        showForm(false);
        showError(error, 'This invitation link does not work here: sign-up is closed on this server; ask its administrator for an account.');
        return;
      }
      $('signup-invitation').value = code;
      showForm(true);
    };
    if (pending !== null) useInvitation(pending);
    pending = null;
  });
}
