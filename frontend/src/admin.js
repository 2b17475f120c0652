// The Admin tab (issue #56), shown to administrators only (GET /api/session says `admin`): every
// account with its role, state, disk use, running jobs and last sign-in, and what `swarmdesign
// admin` does to one: disable or enable, a new one-time password (shown here once), the
// administrator role, delete with everything it owns (its name typed again). Quotas too (`swarmdesign
// admin quota`): each account's disk use of its limit and the runs of work it started today of its
// per-day limit, "(default)" where it follows the server's default; a dialog setting an account's
// two limits, and a form below the table for the server's default. Invitations too, for a server
// run with `--sign-up invite` (`swarmdesign admin invite`): a new one's link shown once, in the
// dialog that made it (only the code's hash is kept); the list with each one's state, and Revoke
// for an unused one.
import { api } from './api.js';
import { confirmDelete } from './confirm_dialog.js';
import { bytesText, countText } from './numbers.js';
import { el } from './properties.js';
import { full, refreshQuota, useText } from './quota.js';

const $ = (id) => document.getElementById(id);

function when(seconds) { return seconds === null ? 'never' : new Date(seconds * 1000).toISOString().slice(0, 16).replace('T', ' ') + ' UTC'; }

/// A limit in bytes as the MB field shows it: empty for no limit.
const mbText = (bytes) => (bytes === null || bytes === undefined ? '' : String(bytes / 1e6));
/// A limit as its field shows it: empty for no limit.
const runsText = (runs) => (runs === null || runs === undefined ? '' : String(runs));
/// A field's text as a limit: null for empty (no limit); an Error naming the field otherwise.
function limitOf(text, what, toUnits, whole) {
  const t = text.trim();
  if (t === '') return null;
  const v = Number(t);
  if (!Number.isFinite(v) || v < 0 || (whole && !Number.isInteger(v))) throw new Error(`${what}: ${whole ? 'a whole number' : 'a number'} of 0 or more, or empty for no limit`);
  return Math.round(v * toUnits);
}
const limitPhrase = (limit, format) => (limit === null || limit === undefined ? 'no limit' : format(limit));

export function initAdmin({ me }) {
  const note = (text, testid = 'admin-note') => $('admin-note').replaceChildren(el('div', { testid, text }));
  let serverDefault = { disk_limit: null, runs_per_day: null };

  // The server's default quota, under the table: empty fields are no limit.
  const defaultDisk = el('input', { type: 'number', min: '0', step: 'any', testid: 'admin-default-disk', placeholder: 'no limit', 'aria-label': 'default disk limit in MB' });
  const defaultRuns = el('input', { type: 'number', min: '0', step: '1', testid: 'admin-default-runs', placeholder: 'no limit', 'aria-label': 'default runs per day' });
  let defaultEdited = false;  // typed into and not saved: a refresh leaves the fields alone
  for (const input of [defaultDisk, defaultRuns]) input.addEventListener('input', () => { defaultEdited = true; });
  const defaultForm = el('form', { class: 'admin-default row small', testid: 'admin-default-form' },
    el('strong', { text: 'Server default quota' }),
    el('label', { class: 'inline' }, 'disk', defaultDisk, 'MB'),
    el('label', { class: 'inline' }, 'runs per day', defaultRuns),
    el('button', { type: 'submit', class: 'small', testid: 'admin-default-save', text: 'Save default' }),
    el('span', { class: 'muted', text: 'Empty: no limit. Accounts marked (default) follow it; a design counts its budget against the day\'s runs when it starts.' }));
  defaultForm.addEventListener('submit', async (e) => {
    e.preventDefault();
    try {
      const body = { disk_limit: limitOf(defaultDisk.value, 'disk', 1e6, false), runs_per_day: limitOf(defaultRuns.value, 'runs per day', 1, true) };
      serverDefault = await api('/api/admin/quota', { body, quiet: true });
      defaultEdited = false;
      note(`server default: disk ${limitPhrase(serverDefault.disk_limit, bytesText)}, runs per day ${limitPhrase(serverDefault.runs_per_day, countText)}`);
    } catch (err) {
      note(err.message, 'admin-error');
    }
    await refresh();
  });
  $('admin-note').before(defaultForm);

  async function saveQuota(name, body) {
    await api(`/api/admin/users/${encodeURIComponent(name)}/quota`, { body, quiet: true });
    note(`${name}: quota set`);
    await refresh();
  }

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
    const quota = el('button', { type: 'button', class: 'small', testid: `admin-quota-${a.name}`, text: 'Quota…',
      onclick: () => quotaDialog(a, serverDefault, (body) => saveQuota(a.name, body)) });
    const buttons = self ? [quota, el('span', { class: 'muted small', text: 'you' })] : [quota,
      el('button', { type: 'button', class: 'small', testid: `admin-${a.disabled ? 'enable' : 'disable'}-${a.name}`,
        text: a.disabled ? 'Enable' : 'Disable', onclick: () => act(a.name, a.disabled ? 'enable' : 'disable') }),
      el('button', { type: 'button', class: 'small', testid: `admin-reset-${a.name}`, text: 'New password', onclick: () => act(a.name, 'reset-password') }),
      el('button', { type: 'button', class: 'small', testid: `admin-role-${a.name}`, text: a.role === 'admin' ? 'Make user' : 'Make admin',
        onclick: () => act(a.name, 'role', { role: a.role === 'admin' ? 'user' : 'admin' }) }),
      el('button', { type: 'button', class: 'small danger', testid: `admin-delete-${a.name}`, text: 'Delete', onclick: async () => {
        const sure = await confirmDelete({ title: `Delete account ${a.name}?`, typeToConfirm: a.name,
          text: `Its projects, designs, experiments and files go with it (${bytesText(a.disk_bytes)}). Nothing of another account is touched.` });
        if (sure) await act(a.name, 'delete', { confirm: a.name });
      } }),
    ];
    const q = a.quota || { disk_limit: null, runs_per_day: null, runs_today: 0, disk_from_default: true, runs_from_default: true };
    return el('tr', { testid: `admin-row-${a.name}` },
      el('td', { text: a.name }), el('td', { text: a.role }),
      el('td', { testid: `admin-state-${a.name}`, text: a.disabled ? 'disabled' : 'active' }),
      quotaCell(`admin-disk-${a.name}`, a.disk_bytes, q.disk_limit, q.disk_from_default, bytesText),
      quotaCell(`admin-runs-${a.name}`, q.runs_today, q.runs_per_day, q.runs_from_default, countText),
      el('td', { class: 'num', text: String(a.running_designs + a.running_experiments) }),
      el('td', { class: 'when', text: when(a.last_sign_in) }),
      // In a box of its own: a flex <td> leaves the table's grid (its border off the row's).
      el('td', {}, el('div', { class: 'row admin-actions' }, ...buttons)));
  }

  async function refresh() {
    try {
      const [list, limits] = await Promise.all([api('/api/admin/users', { quiet: true }), api('/api/admin/quota', { quiet: true })]);
      serverDefault = limits;
      if (!defaultEdited) { defaultDisk.value = mbText(limits.disk_limit); defaultRuns.value = runsText(limits.runs_per_day); }
      $('admin-accounts').replaceChildren(...list.map(row));
    } catch (e) {
      note(e.message, 'admin-error');
    }
    refreshQuota();  // the administrator's own line, if their quota or the default changed
  }

  const invitations = initInvitations();
  return { shown: () => Promise.all([refresh(), invitations.refresh()]) };
}

/// The Invitations section under the accounts: the server's policy, "Invite…", the list.
function initInvitations() {
  const note = (text, testid = 'invite-done') => $('invite-note').replaceChildren(el('div', { testid, text }));
  const policyText = {
    invite: 'This server takes sign-ups by invitation (run-exp --sign-up invite): whoever opens an invitation\'s link signs up once, before it expires.',
    open: 'This server takes sign-ups from anyone who reaches it (run-exp --sign-up open): no invitation is needed.',
    closed: 'Sign-up is closed on this server (run-exp --sign-up closed, the default): an invitation works once it runs with --sign-up invite.',
  };

  async function revoke(id) {
    const sure = await confirmDelete({ title: `Revoke invitation ${id}?`, action: 'Revoke',
      text: 'Its link no longer signs anyone up. Whoever has it will need another.' });
    if (!sure) return;
    try {
      await api(`/api/admin/invitations/${id}/revoke`, { body: {}, quiet: true });
      note(`invitation ${id} revoked`);
    } catch (e) {
      note(e.message, 'invite-error');
    }
    await refresh();
  }

  function row(i) {
    const open = i.state === 'open';
    return el('tr', { testid: `invitation-row-${i.id}` },
      el('td', { class: 'num', text: String(i.id) }),
      el('td', { class: `invitation-state ${i.state}`, testid: `invitation-state-${i.id}`, text: i.state }),
      el('td', { text: i.created_by ?? '(a deleted account)' }),
      el('td', { class: 'when', text: when(i.expires_at) }),
      el('td', { testid: `invitation-used-${i.id}`,
        text: i.state === 'used' ? `${i.used_by ?? '(a deleted account)'}, ${when(i.used_at)}` : '' }),
      el('td', {}, ...(open ? [el('button', { type: 'button', class: 'small danger', testid: `invitation-revoke-${i.id}`,
        text: 'Revoke', onclick: () => revoke(i.id) })] : [])));
  }

  async function refresh() {
    try {
      const [list, policy] = await Promise.all([api('/api/admin/invitations', { quiet: true }),
        api('/api/sign-up', { quiet: true }).then((a) => a.policy).catch(() => 'closed')]);
      $('invite-policy').textContent = policyText[policy] || policyText.closed;
      $('admin-invitations').replaceChildren(...(list.length ? list.map(row)
        : [el('tr', {}, el('td', { colspan: '6', class: 'muted', testid: 'invitations-none', text: 'No invitations yet.' }))]));
    } catch (e) {
      note(e.message, 'invite-error');
    }
  }

  $('invite-button').onclick = () => inviteDialog(async (days) => {
    const made = await api('/api/admin/invitations', { body: { days }, quiet: true });
    $('invite-note').replaceChildren();
    await refresh();
    return made;
  });
  return { refresh };
}

/// "Invite…": how many days the invitation lasts; then, in the same dialog, its link, shown only now.
function inviteDialog(make) {
  const days = el('input', { type: 'number', min: '1', max: '90', step: '1', value: '7', testid: 'invite-days', required: '' });
  const message = el('p', { class: 'small', testid: 'invite-message' });
  const ok = el('button', { type: 'submit', class: 'primary', testid: 'invite-ok', text: 'Make invitation' });
  const cancel = el('button', { type: 'button', testid: 'invite-cancel', text: 'Cancel' });
  const form = el('form', { class: 'stack' }, el('strong', { text: 'Invite someone to sign up' }),
    el('p', { class: 'muted small', text: 'One person signs up with it, once, before it expires. You will see its link only once, right after it is made.' }),
    el('label', { class: 'inline invite-days' }, 'Valid for', days, el('span', { class: 'muted small', text: 'days (1 to 90)' })),
    message, el('div', { class: 'row' }, cancel, ok));
  const dialog = el('dialog', { class: 'confirm-dialog invite-dialog', testid: 'invite-dialog' }, form);
  form.addEventListener('submit', async (e) => {
    e.preventDefault();
    message.classList.remove('error');
    const n = Number(days.value);
    if (!Number.isInteger(n) || n < 1 || n > 90) {
      message.classList.add('error');
      message.textContent = 'days: a whole number of 1 to 90';
      return;
    }
    ok.disabled = true;
    try {
      shown(await make(n));
    } catch (err) {
      message.classList.add('error');
      message.textContent = err.message;
      ok.disabled = false;
    }
  });
  // The new invitation: its link (copy), its code, when it expires; gone once the dialog closes.
  function shown(made) {
    const link = `${location.origin}/#invite=${made.code}`;
    const field = el('input', { readonly: '', value: link, testid: 'invite-link', 'aria-label': 'invitation link',
      onfocus: (e) => e.target.select() });
    const copied = el('span', { class: 'muted small', testid: 'invite-copied', role: 'status' });
    const copy = el('button', { type: 'button', testid: 'invite-copy', text: 'Copy', onclick: async () => {
      field.focus();
      field.select();
      let done = false;
      try { await navigator.clipboard.writeText(link); done = true; } catch { done = document.execCommand && document.execCommand('copy'); }
      copied.textContent = done ? 'copied' : 'select the link and copy it';
    } });
    const close = el('button', { type: 'button', class: 'primary', testid: 'invite-close', text: 'Done' });
    close.addEventListener('click', () => dialog.close());
    form.replaceWith(el('div', { class: 'stack' },
      el('strong', { text: `Invitation ${made.id}` }),
      el('p', { class: 'small', text: `Send this link to the person you invite; it signs up one account until ${when(made.expires_at)}.` }),
      el('div', { class: 'row invite-link-row' }, field, copy, copied),
      el('p', { class: 'small' }, 'Code: ', el('code', { testid: 'invite-code', text: made.code })),
      el('p', { class: 'small invite-once', testid: 'invite-once',
        text: 'Shown only now: the server keeps only a hash of the code. Lost, revoke it and make another.' }),
      el('div', { class: 'row' }, close)));
    field.focus();
  }
  cancel.addEventListener('click', () => dialog.close());
  dialog.addEventListener('close', () => dialog.remove());
  document.body.append(dialog);
  dialog.showModal();
  days.focus();
  days.select();
}

/// "1.2 MB of 100.0 MB (default)": what is used of the limit in force; full when at or over it.
function quotaCell(testid, used, limit, fromDefault, format) {
  return el('td', { class: `quota-cell${full(used, limit) ? ' full' : ''}`, testid },
    useText(used, limit, format), ...(fromDefault ? [el('span', { class: 'muted', text: ' (default)' })] : []));
}

/// An account's two limits: each the server's default, or its own (empty: no limit).
function quotaDialog(account, serverDefault, save) {
  const q = account.quota || { disk_limit: null, runs_per_day: null, disk_from_default: true, runs_from_default: true };
  const message = el('p', { class: 'small', testid: 'quota-message' });
  function limitField(key, label, unit, current, fromDefault, asText, defaultLimit, format, attrs) {
    const input = el('input', { type: 'number', min: '0', placeholder: 'no limit', testid: `quota-${key}`, ...attrs });
    const follow = el('input', { type: 'checkbox', testid: `quota-${key}-default` });
    input.value = fromDefault ? '' : asText(current);
    follow.checked = fromDefault;
    // Following the default, the field shows the default's value, greyed.
    const sync = () => { input.disabled = follow.checked; input.placeholder = follow.checked ? asText(defaultLimit) || 'no limit' : 'no limit'; };
    follow.addEventListener('change', () => { sync(); if (!follow.checked) input.focus(); });
    sync();
    const box = el('div', { class: 'stack' },
      el('label', { class: 'quota-field' }, label, el('span', { class: 'row' }, input, el('span', { class: 'muted small', text: unit }))),
      el('label', { class: 'inline small' }, follow, `server default (${limitPhrase(defaultLimit, format)})`));
    return { box, value: () => (follow.checked ? 'default' : input.value) };
  }
  const disk = limitField('disk', 'Disk', 'MB', q.disk_limit, q.disk_from_default, mbText, serverDefault.disk_limit, bytesText, { step: 'any' });
  const runs = limitField('runs', 'Simulation runs per day (UTC)', 'runs', q.runs_per_day, q.runs_from_default, runsText,
    serverDefault.runs_per_day, countText, { step: '1' });
  const ok = el('button', { type: 'submit', class: 'primary', testid: 'quota-ok', text: 'Save' });
  const cancel = el('button', { type: 'button', testid: 'quota-cancel', text: 'Cancel' });
  const form = el('form', { class: 'stack' }, el('strong', { text: `Quota of ${account.name}` }),
    el('p', { class: 'muted small', text: `Uses ${bytesText(account.disk_bytes)}; started ${countText(q.runs_today ?? 0)} runs today. Empty: no limit. `
      + 'Work already started goes on; what would pass a limit is refused.' }),
    disk.box, runs.box, message, el('div', { class: 'row' }, cancel, ok));
  const dialog = el('dialog', { class: 'confirm-dialog quota-dialog', testid: 'quota-dialog' }, form);
  form.addEventListener('submit', async (e) => {
    e.preventDefault();
    message.classList.remove('error');
    try {
      const asked = (value, what, toUnits, whole) => (value === 'default' ? 'default' : limitOf(value, what, toUnits, whole));
      await save({ disk_limit: asked(disk.value(), 'disk', 1e6, false), runs_per_day: asked(runs.value(), 'runs per day', 1, true) });
      dialog.close();
    } catch (err) {
      message.classList.add('error');
      message.textContent = err.message;
    }
  });
  cancel.addEventListener('click', () => dialog.close());
  dialog.addEventListener('click', (e) => { if (e.target === dialog) dialog.close(); });
  dialog.addEventListener('close', () => dialog.remove());
  document.body.append(dialog);
  dialog.showModal();
  form.querySelector('input:not(:disabled)')?.focus();
}
