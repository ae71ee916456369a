#pragma once
// The HTTP server's queue of connections the kernel has accepted for it but
// its accept thread has not taken yet. Debian's httplib (0.11, a shared
// library, so its compile-time setting cannot be changed from here) listens
// with a queue of 5. When the cores are busy rendering and several clients
// reconnect at once (a kept-alive connection is closed after 5 requests),
// the kernel drops the handshakes past it: the client waits a second for its
// SYN to be sent again, or sees its connection end without an answer
// (docs/performance.md, "The default frame and its floor").
namespace toond::http {

// Calls listen() again, with room for `backlog` waiting connections, on
// every listening TCP socket of this process bound to `port` (Linux takes a
// second listen() on a listening socket as a new queue length, capped by
// net.core.somaxconn). Returns how many sockets it widened.
int widen_listen_backlog(int port, int backlog);

}  // namespace toond::http
