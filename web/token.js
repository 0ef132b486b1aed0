// The service's API token (lenslab serve --token-file; docs/api.md, "Access"), typed once into the
// header's field and sent as "Authorization: Bearer TOKEN" with every request the page makes.
// Kept in sessionStorage, not localStorage: the token lets its holder write and spend the
// server's CPU, so it lives only as long as this tab and is not left behind on a shared machine;
// the cost is typing it again in a new tab.

const STORAGE_KEY = "lenslab.apiToken";

const field = () => document.getElementById("token-input");
const status = () => document.getElementById("token-status");

export function apiToken() {
  try {
    return sessionStorage.getItem(STORAGE_KEY) || "";
  } catch (e) {
    return "";  // storage disabled: the field's value still serves this page
  }
}

// Headers carrying the token, merged into `headers` (a plain object); unchanged when none is set.
export function withToken(headers = {}) {
  const token = apiToken();
  return token ? { ...headers, Authorization: `Bearer ${token}` } : headers;
}

// Called when the server answered 401: says so next to the field and puts the keyboard there.
export function tokenRefused() {
  status().textContent = apiToken()
    ? "Refused (401): this is not the server's token; compare it with the file given to --token-file."
    : "Refused (401): this needs the server's API token; paste it here (the file given to --token-file).";
  status().className = "token-status refused";
  field().focus();
}

function saveToken(value) {
  const token = value.trim();
  try {
    if (token) sessionStorage.setItem(STORAGE_KEY, token);
    else sessionStorage.removeItem(STORAGE_KEY);
  } catch (e) {
    // storage disabled: nothing to keep
  }
  status().textContent = token ? "Token set for this tab." : "";
  status().className = "token-status";
}

export function setUpTokenField() {
  const input = field();
  input.value = apiToken();
  input.addEventListener("change", () => saveToken(input.value));
  document.getElementById("token-form").addEventListener("submit", (e) => { e.preventDefault(); saveToken(input.value); });
}
