// Debian's Chromium, headless, driven by playwright-core: the one launch the page tests share
// (check_page.mjs, check_viewer.mjs). WebGL through SwiftShader, as the machines have no GPU;
// no background traffic, so a request off the local server is the page's own.
import { chromium } from 'playwright-core';

// A persistent context in `profile` (a fresh folder), 1024 x 640.
export function launchHeadlessChromium(profile) {
  return chromium.launchPersistentContext(profile, {
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    viewport: { width: 1024, height: 640 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync',
           '--enable-unsafe-swiftshader', '--use-angle=swiftshader'],
  });
}
