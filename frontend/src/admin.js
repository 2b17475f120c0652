// The Admin tab (issue #56), shown to administrators only (GET /api/session says `admin`): every
// account with its role, state, disk use, running jobs and last sign-in, and what `swarmdesign
// admin` does to one: disable or enable, a new one-time password (shown here once), the
// administrator role, delete with everything it owns (its name typed again).
import { api } from './api.js';
import { confirmDelete } from './confirm_dialog.js';
import { el } from './properties.js';

const $ = (id) => document.getElementById(id);

function megabytes(bytes) { return `${(bytes / 1e6).toFixed(1)} MB`; }
function when(seconds) { return seconds === null ? 'never' : new Date(seconds * 1000).toISOString().slice(0, 16).replace('T', ' ') + ' UTC'; }

export function initAdmin({ me }) {
  const note = (text, testid = 'admin-note') => $('admin-note').replaceChildren(el('div', { testid, text }));

  async function act(name, verb, body = {}) {
    try {
      const answer = await api(`/api/admin/users/${encodeURIComponent(name)}/${verb}`, { body, quiet: true });
      if (verb === 'reset-password')
        $('admin-note').replaceChildren(el('div', { class: 'new-password' },
          `New password for ${answer.name} (shown once; their sessions ended): `,
          el('code', { testid: 'admin-new-password', text: answer.password })));
      else note(`${name}: done`);
    } catch (e) {
      note(e.message, 'admin-error');
    }
    await refresh();
  }

  function row(a) {
    const self = a.name === me();
    const buttons = self ? [el('span', { class: 'muted small', text: 'you' })] : [
      el('button', { type: 'button', class: 'small', testid: `admin-${a.disabled ? 'enable' : 'disable'}-${a.name}`,
        text: a.disabled ? 'Enable' : 'Disable', onclick: () => act(a.name, a.disabled ? 'enable' : 'disable') }),
      el('button', { type: 'button', class: 'small', testid: `admin-reset-${a.name}`, text: 'New password', onclick: () => act(a.name, 'reset-password') }),
      el('button', { type: 'button', class: 'small', testid: `admin-role-${a.name}`, text: a.role === 'admin' ? 'Make user' : 'Make admin',
        onclick: () => act(a.name, 'role', { role: a.role === 'admin' ? 'user' : 'admin' }) }),
      el('button', { type: 'button', class: 'small danger', testid: `admin-delete-${a.name}`, text: 'Delete', onclick: async () => {
        const sure = await confirmDelete({ title: `Delete account ${a.name}?`, typeToConfirm: a.name,
          text: `Its projects, designs, experiments and files go with it (${megabytes(a.disk_bytes)}). Nothing of another account is touched.` });
        if (sure) await act(a.name, 'delete', { confirm: a.name });
      } }),
    ];
    return el('tr', { testid: `admin-row-${a.name}` },
      el('td', { text: a.name }), el('td', { text: a.role }),
      el('td', { testid: `admin-state-${a.name}`, text: a.disabled ? 'disabled' : 'active' }),
      el('td', { class: 'num', text: megabytes(a.disk_bytes) }),
      el('td', { class: 'num', text: String(a.running_designs + a.running_experiments) }),
      el('td', { text: when(a.last_sign_in) }),
      el('td', { class: 'row' }, ...buttons));
  }

  async function refresh() {
    try {
      const list = await api('/api/admin/users', { quiet: true });
      $('admin-accounts').replaceChildren(...list.map(row));
    } catch (e) {
      note(e.message, 'admin-error');
    }
  }

  return { shown: refresh };
}
