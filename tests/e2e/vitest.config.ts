import { defineConfig } from "vitest/config";

// End-to-end tests: the built dist/ served on 127.0.0.1, driven in headless Debian Chromium.
// With E2E_DIST=dist-foon111 (a build bundling FOON-111), only the FOON-111 tests run against that build.
const foon111 = process.env.E2E_DIST !== undefined;
export default defineConfig({
  test: {
    root: new URL("../..", import.meta.url).pathname,
    include: foon111 ? ["tests/e2e/foon111.e2e.ts"] : ["tests/e2e/**/*.e2e.ts"],
    exclude: foon111 ? [] : ["tests/e2e/foon111.e2e.ts"],
    globalSetup: ["tests/e2e/global-setup.ts"],
    testTimeout: 60_000,
    hookTimeout: 60_000,
    fileParallelism: false,
  },
});
