// The Missions tab: every mission drawn by the server, with its description, duration and objective.
import { el } from './properties.js';

export function renderMissions(container, missions, onTry) {
  container.replaceChildren(...missions.map((m) => el('div', { class: 'mission-card', testid: `mission-${m.name}` },
    el('img', { src: `/api/missions/svg?name=${encodeURIComponent(m.name)}`, alt: `arena of ${m.name}`, loading: 'lazy' }),
    el('div', { class: 'title', text: m.title }),
    el('div', { class: 'name', text: `${m.name} · ${m.origin || ''}` }),
    el('div', { class: 'small', text: m.description || '' }),
    el('div', { class: 'small muted', text: `${m.robots} robots · ${m.duration_s} s${m.ticks ? ` (${m.ticks} ticks)` : ''}` }),
    el('div', { class: 'small muted', text: `objective: ${m.objective || '?'} (${m.direction})` }),
    el('button', { text: 'Try in Exec', onclick: () => onTry(m.name) }))));
}
