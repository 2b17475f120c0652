// Asking before something is deleted: a modal <dialog> saying what goes, and, for a whole
// project, the project's name typed again (the server asks for it too). Resolves true only when
// the user confirms; Escape, Cancel or a click outside resolve false.
import { el } from './properties.js';

// `warning`, when given, is said apart from the text: what the deletion breaks elsewhere.
export function confirmDelete({ title, text, warning = null, typeToConfirm = null, action = 'Delete' }) {
  return new Promise((resolve) => {
    const input = typeToConfirm === null ? null
      : el('input', { testid: 'confirm-name', autocomplete: 'off', placeholder: typeToConfirm, 'aria-label': `type ${typeToConfirm} to confirm` });
    const ok = el('button', { type: 'submit', class: 'danger', testid: 'confirm-ok', text: action });
    const cancel = el('button', { type: 'button', testid: 'confirm-cancel', text: 'Cancel' });
    const form = el('form', { method: 'dialog', class: 'stack' },
      el('strong', { text: title }),
      el('p', { class: 'small', text }),
      ...(warning ? [el('p', { class: 'small confirm-warning', testid: 'confirm-warning', text: warning })] : []),
      ...(input ? [el('label', { text: `Type ${typeToConfirm} to confirm` }), input] : []),
      el('div', { class: 'row' }, cancel, ok));
    const dialog = el('dialog', { class: 'confirm-dialog', testid: 'confirm-dialog' }, form);
    let answer = false;
    if (input) {
      ok.disabled = true;
      input.addEventListener('input', () => { ok.disabled = input.value !== typeToConfirm; });
    }
    form.addEventListener('submit', () => { answer = !input || input.value === typeToConfirm; });
    cancel.addEventListener('click', () => dialog.close());
    dialog.addEventListener('click', (e) => { if (e.target === dialog) dialog.close(); });
    dialog.addEventListener('close', () => { dialog.remove(); resolve(answer); });
    document.body.append(dialog);
    dialog.showModal();
    (input || cancel).focus();
  });
}
