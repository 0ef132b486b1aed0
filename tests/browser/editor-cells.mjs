// The prescription editor as the browser tests drive it: typing into a cell and waiting for that
// edit's preview, and selecting a lens until its prescription is in the editor.

// The number of previews the page has shown.
export const previews = (page) => page.$eval("#editor", (e) => Number(e.dataset.previews || 0));

// Types into a cell and waits for the preview of that edit: the time from the input event to the
// new numbers and diagram on screen, as the page measures it.
export async function editCell(page, row, key, text) {
  const before = await previews(page);
  const input = `#editor-table input[data-row="${row}"][data-key="${key}"]`;
  await page.fill(input, text);
  await page.press(input, "Tab");
  await page.waitForFunction((n) => Number(document.querySelector("#editor").dataset.previews || 0) > n, before)
    .catch(async (e) => { throw new Error(`no preview after "${text}" in ${input}: ${await page.textContent("#editor-status")}`, { cause: e }); });
  return page.$eval("#editor", (e) => Number(e.dataset.previewMs));
}

// Waits until the editor holds lens `id`'s prescription and its diagram is shown.
export async function editorHolds(page, id) {
  await page.waitForFunction((id) => document.querySelector("#editor").dataset.lens === id, id);
  await page.waitForFunction(() => document.querySelector("#diagram").src.startsWith("blob:"));
}
