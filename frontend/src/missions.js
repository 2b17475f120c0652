// The Missions tab: every mission drawn by the server, with its description, duration and
// objective, and the form that brings a user's own mission file into one of their projects.
import { api } from './api.js';
import { el } from './properties.js';
import { quotaRefused, refreshQuota } from './quota.js';
import { clearError } from './toast.js';

export function renderMissions(container, missions, onTry) {
  container.replaceChildren(...missions.map((m) => el('div', { class: 'mission-card', testid: `mission-${m.name}` },
    el('img', { src: `/api/missions/svg?name=${encodeURIComponent(m.name)}`, alt: `arena of ${m.name}`, loading: 'lazy' }),
    el('div', { class: 'title', text: m.title }),
    el('div', { class: 'name', text: `${shortName(m)} · ${m.origin || ''}`, title: m.name }),
    el('div', { class: 'small', text: m.description || '' }),
    el('div', { class: 'small muted', text: `${m.robots} robots · ${m.duration_s} s${m.ticks ? ` (${m.ticks} ticks)` : ''}` }),
    el('div', { class: 'small muted', text: `objective: ${m.objective || '?'} (${m.direction})` }),
    el('button', { text: 'Try in Exec', onclick: () => onTry(m.name) }))));
}

/// A mission file's name as its project and file ("mine/corner.json"); a catalogue name as is.
/// The whole path stays in the title, shown on hover.
export function shortName(m) {
  if (!m.name.includes('/')) return m.name;
  const parts = m.name.split('/');
  const file = parts.pop();
  if (parts[parts.length - 1] === 'missions') parts.pop();
  return `${parts.pop()}/${file}`;
}

/// The upload form: the file's text is sent as is; the server validates it as the CLI reads a
/// mission file and answers one line naming what is wrong, storing nothing then.
export function initMissionUpload({ onUploaded }) {
  const $ = (id) => document.getElementById(id);
  const status = $('upload-status');
  const say = (text, kind) => { status.textContent = text; status.className = `small ${kind}`; };
  $('upload-file').addEventListener('change', () => {
    const file = $('upload-file').files[0];
    if (file && !$('upload-name').value) $('upload-name').value = file.name.replace(/\.json$/i, '').replace(/[^A-Za-z0-9_-]/g, '-').slice(0, 64);
    say('', '');
  });
  $('mission-upload').addEventListener('submit', async (event) => {
    event.preventDefault();
    const file = $('upload-file').files[0];
    const project = $('upload-project').value;
    if (!file || !project) return;
    if (file.size > 1 << 20) { say(`${file.name} is larger than 1 MiB`, 'error'); return; }
    say('uploading…', 'muted');
    try {
      const mission = await api(`/api/projects/${encodeURIComponent(project)}/missions`,
        { body: { name: $('upload-name').value, text: await file.text() }, quiet: true });
      say(`added ${mission.title} to ${project}: choose it for a project (Designs tab, Set mission) or try it in Exec`, 'done');
      $('mission-upload').reset();
      clearError();  // a refusal shown before is stale
      refreshQuota();
      await onUploaded(mission);
    } catch (e) {
      quotaRefused(e);
      say(e.message, 'error');
    }
  });
  return {
    async refreshProjects() {
      const projects = await api('/api/projects', { quiet: true }).catch(() => []);
      const before = $('upload-project').value;
      $('upload-project').replaceChildren(...projects.map((p) => el('option', { value: p.name, text: p.name })));
      if (projects.some((p) => p.name === before)) $('upload-project').value = before;
      $('upload-button').disabled = projects.length === 0;
      if (projects.length === 0) say('create a project first (Designs tab), then add missions to it', 'muted');
    },
  };
}
