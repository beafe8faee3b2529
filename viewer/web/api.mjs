// The server's API (viewer/api.h lists it). Every failure throws an Error carrying the server's
// {"error": ...} message.

async function checked(response) {
    if (response.ok) return response;
    let message = `${response.status} ${response.statusText}`;
    try {
        message = (await response.json()).error || message;
    } catch (_) { /* not JSON: keep the status line */ }
    throw new Error(message);
}

const getJson = async (path) => (await checked(await fetch(path))).json();
const post = async (path, body, type = 'application/json') =>
    checked(await fetch(path, { method: 'POST', headers: { 'Content-Type': type },
                                body: typeof body === 'string' ? body : JSON.stringify(body) }));

export const imageInfo = () => getJson('/api/image');
export const illuminantNames = async () => (await getJson('/api/illuminants')).names;
export const illuminant = (name) => getJson(`/api/illuminants/${encodeURIComponent(name)}`);

export async function spectra() {
    const response = await checked(await fetch('/api/image/spectra'));
    return new Float32Array(await response.arrayBuffer());  // little-endian, as the page's hosts are
}

// An image in a basis: its k coefficients per pixel.
export async function coefficients() {
    const response = await checked(await fetch('/api/image/coefficients'));
    return new Float32Array(await response.arrayBuffer());
}

export async function relit(light, conversion) {
    const response = await post('/api/relight', { light, conversion });
    return new Float32Array(await response.arrayBuffer());
}

export async function difference(lightA, lightB) {
    const response = await post('/api/difference', { lightA, lightB });
    return { map: new Float32Array(await response.arrayBuffer()),
             mean: Number(response.headers.get('X-Mean-DeltaE')),
             max: Number(response.headers.get('X-Max-DeltaE')) };
}

export const exportImage = async (light, conversion, format) =>
    (await post('/api/export', { light, conversion, format })).blob();
export const loadLight = async (text, name) =>
    (await post(`/api/light/load?name=${encodeURIComponent(name)}`, text, 'text/plain')).json();
export const saveLight = async (request) => (await post('/api/light/save', request)).text();
export const match = async (light, target, conversion) =>
    (await post('/api/match', { light, target, conversion })).json();
