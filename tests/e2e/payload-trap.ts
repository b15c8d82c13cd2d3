// What an injected payload would do on a page, watched from before any script of the page runs: the `xss`
// global the test payloads set, the Content-Security-Policy violations reported, the dialogs opened; and a
// positive signal that the page has handled whatever a payload could have set off, so that "nothing ran" is
// asserted after it could have run, not after a guessed delay.
import type { Page } from "playwright-core";

export interface Trap {
  xss: unknown;
  violations: string[];
  dialogs: string[];
}

export interface PayloadTrap {
  /** What payloads did so far. */
  trap(): Promise<Trap>;
  /** Resolves once the page has handled anything a payload could have set off (see `settle`). */
  settled(): Promise<void>;
}

/** The console's report of a blocked inline event handler. */
const BLOCKED_HANDLER = /^console: Executing inline event handler violates the following Content Security Policy directive/;

/**
 * A probe image with the payloads' own `src=x` (one image resource, so its error event comes after theirs) and
 * an inline error handler, which the policy blocks and reports at the probe (so its report comes after theirs).
 * Resolves when both have come. Were the policy ever to let the handler run, `xss` would be "probe".
 */
async function settle(page: Page): Promise<void> {
  await page.evaluate(
    () =>
      new Promise<void>((resolve) => {
        const probe = document.createElement("img");
        let pending = 2;
        const done = (): void => {
          pending -= 1;
          if (pending > 0) return;
          probe.remove();
          resolve();
        };
        probe.setAttribute("onerror", "window.xss = 'probe'");
        probe.addEventListener("securitypolicyviolation", (e) => {
          e.stopPropagation(); // the probe's own report stays out of the trap
          done();
        });
        probe.addEventListener("error", () => {
          if ((window as unknown as { xss?: unknown }).xss === "probe") pending = 1; // it ran: no report will come
          done();
        });
        probe.src = "x";
        document.body.append(probe);
      }),
  );
}

/**
 * Traps `page` (before its first navigation). `errors` is the page's `watchErrors` list: `settled` takes the
 * probe's own console report out of it, so that a payload's report is all that can remain.
 */
export async function setTrap(page: Page, errors: string[]): Promise<PayloadTrap> {
  const dialogs: string[] = [];
  page.on("dialog", (d) => {
    dialogs.push(d.message());
    void d.dismiss();
  });
  await page.addInitScript(() => {
    const w = window as unknown as { cspViolations: string[] };
    w.cspViolations = [];
    document.addEventListener("securitypolicyviolation", (e) => w.cspViolations.push(`${e.violatedDirective}: ${e.sample}`));
  });
  const trap = async (): Promise<Trap> => {
    const seen = await page.evaluate(() => {
      const w = window as unknown as { xss?: unknown; cspViolations: string[] };
      return { xss: w.xss ?? null, violations: w.cspViolations };
    });
    return { ...seen, dialogs };
  };
  const settled = async (): Promise<void> => {
    await settle(page);
    // the probe's report is the last of its kind: it came after any payload's
    const probe = errors.map((e) => BLOCKED_HANDLER.test(e)).lastIndexOf(true);
    if (probe < 0) throw new Error(`the probe's blocked handler was not reported on the console: ${errors.join("; ")}`);
    errors.splice(probe, 1);
  };
  return { trap, settled };
}
