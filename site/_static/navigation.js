/* The ☰ button that opens the chapter list, on phones and on desktops.
 *
 * pydata-sphinx-theme 0.17 puts a ☰ button of its own, with the class "primary-toggle", into its
 * top bar, which sphinx-book-theme hides; the button a reader sees is sphinx-book-theme's, in the
 * article's header, with the same class. Both themes wire up only the first element of that class
 * (document.querySelector), that is the hidden one, so the visible button does nothing at any width
 * (pydata-sphinx-theme issue 2451). Here every other "primary-toggle" hands its click to the wired
 * one: on a narrow screen the chapter list opens as a dialog, on a wide one it folds away and back.
 */
(() => {
  "use strict";
  const forward = () => {
    const toggles = [...document.querySelectorAll(".primary-toggle")];
    const wired = toggles[0];
    if (!wired) {
      return;
    }
    for (const button of toggles.slice(1)) {
      if (!button.hasAttribute("aria-label")) {
        button.setAttribute("aria-label", "Chapters of the course");
      }
      button.addEventListener("click", (event) => {
        event.preventDefault();
        event.stopPropagation();
        wired.click();
      });
    }
  };
  if (document.readyState === "loading") {
    document.addEventListener("DOMContentLoaded", forward);
  } else {
    forward();
  }
})();
