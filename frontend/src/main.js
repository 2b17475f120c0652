// Entry point: session check, sign-in, tabs; each tab lives in its own module.
import './style.css';
import { api, setCsrf, whenUnauthorized } from './api.js';
import { loadCatalogue } from './catalogue.js';
import { DEFAULT_TEXT, initEditor } from './editor.js';
import { initExec } from './exec.js';
import { initMissionEditor } from './mission_editor.js';
import { initMissionUpload, renderMissions } from './missions.js';
import { initMonitor } from './monitor.js';
import { copyFullScores } from './numbers.js';
import { initAdmin } from './admin.js';
import { changePasswordDialog } from './password_dialog.js';
import { initQuota, refreshQuota } from './quota.js';
import { showSignIn } from './signin.js';
import { clearError, showError } from './toast.js';

const $ = (id) => document.getElementById(id);
let started = false;
let parts = null;
let missions = [];

function showTab(name) {
  clearError();  // it spoke of the tab left
  for (const page of document.querySelectorAll('[data-page]')) page.hidden = page.dataset.page !== name;
  for (const tab of document.querySelectorAll('.tab')) tab.classList.toggle('active', tab.dataset.tab === name);
  if (history.replaceState) history.replaceState(null, '', `#${name}`);
  if (!parts) return;
  refreshQuota();
  if (name === 'editor') { parts.editor.resize(); parts.editor.refreshProjects(); }
  if (name === 'exec') parts.exec.shown();
  if (name === 'designs') parts.monitor.shown(); else parts.monitor.hidden();
  if (name === 'missions') { parts.upload.refreshProjects(); parts.missionEditor.refreshProjects(); }
  if (name === 'admin' && parts.admin) parts.admin.shown();
}

async function startApp(user) {
  $('user-name').textContent = user;
  $('signin').hidden = true;
  $('app').hidden = false;
  refreshQuota();  // signed in again (perhaps as another account)
  if (started) return;
  started = true;
  initQuota();
  await loadCatalogue();
  const exec = initExec();
  const editor = initEditor({ onExec: (text) => { exec.prepare({ text }); showTab('exec'); } });
  const monitor = initMonitor({
    missions: () => missions,
    onWatch: (text, mission) => { showTab('exec'); exec.prepare({ text, mission, seed: 1, go: true }); },
    onEdit: (text) => { showTab('editor'); editor.load(text); },
    // A deleted project's uploaded missions go with it.
    onProjectsChanged: async () => { showMissions(await api('/api/missions')); editor.refreshProjects(); },
  });
  const showMissions = (list) => {
    missions = list;
    exec.setMissions(missions);
    monitor.setMissions(missions);
    missionEditor.setMissions(missions);
    renderMissions($('mission-grid'), missions, (name) => { exec.prepare({ mission: name, text: $('exec-text').value || editor.current.text }); showTab('exec'); });
  };
  const upload = initMissionUpload({ onUploaded: async () => showMissions(await api('/api/missions')) });
  const missionEditor = initMissionEditor({ onSaved: async () => showMissions(await api('/api/missions')) });
  copyFullScores();
  // An administrator's page has the Admin tab (the server checks the role on every request).
  const session = await api('/api/session', { quiet: true }).catch(() => ({ admin: false }));
  const admin = session.admin ? initAdmin({ me: () => $('user-name').textContent }) : null;
  $('tab-admin').hidden = !admin;
  parts = { editor, exec, monitor, upload, missionEditor, admin };
  window.__sd = parts; // for the end-to-end tests and the curious
  window.__sd.execCounts = () => exec.graph.nodes().reduce((sum, n) => sum + (n.data('count') || 0), 0);
  for (const tab of document.querySelectorAll('.tab')) tab.addEventListener('click', () => showTab(tab.dataset.tab));
  showMissions(await api('/api/missions'));
  exec.prepare({ text: DEFAULT_TEXT, mission: 'aac', seed: 1 });
  const wanted = (location.hash || '#editor').slice(1);
  showTab(['editor', 'exec', 'designs', 'missions', ...(admin ? ['admin'] : [])].includes(wanted) ? wanted : 'editor');
  await editor.load(DEFAULT_TEXT);
  document.body.dataset.ready = 'true';
}

$('user-name').addEventListener('click', () => changePasswordDialog());

$('signout').addEventListener('click', async () => {
  try { await api('/api/sign-out', { body: {} }); } catch { /* signed out anyway */ }
  setCsrf(null);
  location.hash = '';
  location.reload();
});

whenUnauthorized(() => showSignIn(startApp));

(async () => {
  try {
    const session = await api('/api/session', { quiet: true });
    setCsrf(session.csrf);
    const invited = location.hash.startsWith('#invite=');  // an invitation link, opened while signed in
    await startApp(session.user);
    if (invited) showError(`You are signed in as ${session.user}: to sign up with this invitation, sign out and open its link again.`);
  } catch (e) {
    // A 401 has shown the sign-in page already (whenUnauthorized); no answer at all has not.
    if (e.status === 0) showSignIn(startApp);
    else if (e.status !== 401) showError(e.message);
  }
})();
