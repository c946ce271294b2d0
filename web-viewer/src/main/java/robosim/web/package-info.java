/**
 * The browser viewer: {@link robosim.web.WebViewerServer} serves a page (2D and 3D views, a robot's watch
 * panel, status bar, timeline) and a WebSocket feed, on loopback, or over TLS with the simulation's keys.
 * Threads: {@code web-io} (netty's one I/O thread: HTTP, WebSocket frames, writes to pages, every page's
 * state), {@code web-status} (pages' status requests), {@code web-commands} (their other requests, which
 * may wait), {@code web-feed} (connects the feed to the viewer port, again after each simulation) and the
 * feed's {@code viewer-client} (reads the viewer stream and hands each message to the pages without
 * blocking), and for each robot the pages watch {@code web-watch-N} (its feed, {@link robosim.web.WatchFeeds})
 * with its own {@code viewer-client}.
 */
package robosim.web;
