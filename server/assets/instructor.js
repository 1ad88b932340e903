// The instructors' dashboard, live: the page names its events (main[data-events]); on each
// `change` (a submission or a grade anywhere in the class, on any instance) the page's main part
// is fetched again and swapped in, at most once a second. Without JavaScript the page is the
// same, reloaded by hand.
const main = document.querySelector('main[data-events]');

if (main && 'EventSource' in window) {
  let busy = false;
  let again = false;
  const refresh = async () => {
    if (busy) {
      again = true;
      return;
    }
    busy = true;
    try {
      const response = await fetch(location.href, {credentials: 'same-origin'});
      if (response.ok) {
        const page = new DOMParser().parseFromString(await response.text(), 'text/html');
        const fresh = page.querySelector('main[data-events]');
        if (fresh) {
          main.replaceChildren(...Array.from(fresh.childNodes, (n) => document.importNode(n, true)));
          main.dataset.updated = String(Number(main.dataset.updated ?? 0) + 1);
        }
      }
    } catch {
      // The next change tries again.
    } finally {
      setTimeout(() => {
        busy = false;
        if (again) {
          again = false;
          refresh();
        }
      }, 1000);
    }
  };
  const events = new EventSource(main.dataset.events);
  events.addEventListener('change', refresh);
}
