// The comparison page in a real browser (Debian's chromium, headless, driven
// by playwright-core): it loads from a file with no console errors, every
// panel draws something besides the background, and each toggle changes
// the picture. Usage: node compare_page_test.mjs PAGE.html PANELS
import { chromium } from 'playwright-core';
import { pathToFileURL } from 'node:url';

const [page_path, expected_panels] = process.argv.slice(2);
const failures = [];
const check = (ok, what) => { if (!ok) failures.push(what); };

const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
  args: ['--no-sandbox', '--enable-unsafe-swiftshader', '--use-angle=swiftshader'],
});
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 2400 } });
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(pathToFileURL(page_path).href);
  try {
    await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
  } catch {
    console.log(`FAIL: the page did not finish drawing in 30 s; console errors: ${errors.join(' | ')}`);
    process.exit(1);
  }

  const panels = page.locator('.view');
  const count = await panels.count();
  check(count === Number(expected_panels), `panels: ${count}, expected ${expected_panels}`);

  // Pixels of a screenshot that are not the page's white panel background,
  // counted by the browser itself from the PNG.
  const drawn = async (png) => page.evaluate(async (base64) => {
    const image = new Image();
    image.src = 'data:image/png;base64,' + base64;
    await image.decode();
    const canvas = new OffscreenCanvas(image.width, image.height);
    const context = canvas.getContext('2d');
    context.drawImage(image, 0, 0);
    const pixels = context.getImageData(0, 0, image.width, image.height).data;
    let n = 0;
    for (let i = 0; i < pixels.length; i += 4)
      if (pixels[i] < 250 || pixels[i + 1] < 250 || pixels[i + 2] < 250) ++n;
    return n / (image.width * image.height);
  }, png.toString('base64'));

  for (let i = 0; i < count; ++i) {
    const panel = panels.nth(i);
    await panel.scrollIntoViewIfNeeded();
    const fraction = await drawn(await panel.screenshot());
    check(fraction > 0.01, `panel ${i} draws ${(100 * fraction).toFixed(2)}% non-background pixels`);
  }

  await panels.first().scrollIntoViewIfNeeded();
  const before = await page.screenshot();
  await page.click('#wireframe');
  const wire = await page.screenshot();
  check(!before.equals(wire), 'the wireframe toggle did not change the picture');
  await page.click('#cage');
  const no_cage = await page.screenshot();
  check(!wire.equals(no_cage), 'the cage toggle did not change the picture');
  check(errors.length === 0, `console errors: ${errors.join(' | ')}`);
} finally {
  await browser.close();
}
if (failures.length) {
  for (const f of failures) console.log(`FAIL: ${f}`);
  process.exit(1);
}
console.log(`browser: compare page with ${expected_panels} panels passed`);
