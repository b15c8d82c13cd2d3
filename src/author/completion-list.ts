// The editor's list of suggestions under the text: an ARIA listbox the textarea points at
// (aria-activedescendant), moved with the arrow keys, chosen with Enter, Tab or a click.

import { el } from "../app/dom";
import type { Completion } from "./complete";

export interface CompletionList {
  show(completion: Completion | null): void;
  close(): void;
  /** A key pressed in the textarea while the list is open; true when the list used it. */
  key(event: KeyboardEvent): boolean;
}

export function mountCompletionList(list: HTMLUListElement, input: HTMLTextAreaElement, choose: (completion: Completion, option: string) => void): CompletionList {
  let completion: Completion | null = null;
  let active = 0;

  const close = (): void => {
    completion = null;
    list.hidden = true;
    input.removeAttribute("aria-activedescendant");
  };

  const activate = (index: number): void => {
    active = index;
    list.querySelectorAll("li").forEach((li, i) => li.setAttribute("aria-selected", i === active ? "true" : "false"));
    input.setAttribute("aria-activedescendant", `${list.id}-${active}`);
  };

  const accept = (index: number): void => {
    const current = completion;
    const option = current?.options[index];
    close();
    if (current !== null && option !== undefined) choose(current, option);
  };

  return {
    show(next) {
      if (next === null) return close();
      completion = next;
      list.replaceChildren(
        ...next.options.map((option, i) => {
          const item = el("li", { id: `${list.id}-${i}`, role: "option", text: option });
          item.addEventListener("mousedown", (event) => {
            event.preventDefault(); // the focus stays in the textarea
            accept(i);
          });
          return item;
        }),
      );
      list.hidden = false;
      activate(0);
    },
    close,
    key(event) {
      if (completion === null) return false;
      const count = completion.options.length;
      if (event.key === "ArrowDown" || event.key === "ArrowUp") activate((active + (event.key === "ArrowDown" ? 1 : -1) + count) % count);
      else if (event.key === "Enter" || event.key === "Tab") accept(active);
      else if (event.key === "Escape") close();
      else return false;
      event.preventDefault();
      return true;
    },
  };
}
