// Changing one's own password (POST /api/password, `swarmdesign change-password`): the current
// one, the new one twice; every other session of the account ends, this page stays signed in.
import { api } from './api.js';
import { el } from './properties.js';

export function changePasswordDialog() {
  const field = (testid, label) => el('label', { class: 'stack small' }, label,
    el('input', { type: 'password', testid, autocomplete: testid === 'password-current' ? 'current-password' : 'new-password', required: '' }));
  const message = el('p', { class: 'small', testid: 'password-message' });
  const ok = el('button', { type: 'submit', testid: 'password-ok', text: 'Change password' });
  const cancel = el('button', { type: 'button', testid: 'password-cancel', text: 'Close' });
  const form = el('form', { class: 'stack' }, el('strong', { text: 'Change your password' }),
    field('password-current', 'Current password'), field('password-new', 'New password'), field('password-again', 'New password again'),
    el('p', { class: 'muted small', text: 'Your other sessions (other pages, terminals) end; this page stays signed in.' }),
    message, el('div', { class: 'row' }, cancel, ok));
  const dialog = el('dialog', { class: 'confirm-dialog', testid: 'password-dialog' }, form);
  const value = (testid) => form.querySelector(`[data-testid="${testid}"]`).value;
  form.addEventListener('submit', async (e) => {
    e.preventDefault();
    message.classList.remove('error');
    if (value('password-new') !== value('password-again')) {
      message.classList.add('error');
      message.textContent = 'The two new passwords differ.';
      return;
    }
    try {
      await api('/api/password', { body: { current: value('password-current'), new: value('password-new') }, quiet: true });
      message.textContent = 'Password changed.';
      for (const input of form.querySelectorAll('input')) input.value = '';
    } catch (err) {
      message.classList.add('error');
      message.textContent = err.message;
    }
  });
  cancel.addEventListener('click', () => dialog.close());
  dialog.addEventListener('close', () => dialog.remove());
  document.body.append(dialog);
  dialog.showModal();
  form.querySelector('input').focus();
}
