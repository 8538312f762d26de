/* The landing page's course map, on a phone: site.css lays each row out as a card; here each cell
 * gets its column's heading as data-label, which the card shows before the cell's text. The table
 * is the one whose headings include "Notebook". */
(() => {
  "use strict";
  const label = () => {
    for (const table of document.querySelectorAll(".bd-article table")) {
      const headings = [...table.querySelectorAll("thead th")].map((th) => th.textContent.trim());
      if (!headings.includes("Notebook")) {
        continue;
      }
      table.classList.add("course-map");
      for (const row of table.querySelectorAll("tbody tr")) {
        [...row.children].forEach((cell, column) => {
          if (headings[column]) {
            cell.dataset.label = headings[column];
          }
        });
      }
    }
  };
  if (document.readyState === "loading") {
    document.addEventListener("DOMContentLoaded", label);
  } else {
    label();
  }
})();
