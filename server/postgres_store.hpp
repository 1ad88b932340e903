// The store for several `frustum serve` instances behind a load balancer: PostgreSQL through
// libpq. Migrations run under an advisory lock, so that of N instances starting at once exactly
// one migrates; pending gradings are claimed as rows (FOR UPDATE SKIP LOCKED) with a lease.
#pragma once

#include <memory>
#include <string>

#include "server/store.hpp"

namespace frustum::server {

struct PostgresOptions {
  int connections = 4;  // at most this many open at once (each thread uses one at a time)
  // A grading worker's claims and grades may reach the disk after their commit returns
  // (synchronous_commit off): one lost in a crash of the database server leaves its submission
  // pending, graded again, still once. Submissions always wait for the disk.
  bool worker = false;
};

// Applies the missing migrations of the database at `url` and returns how many this call
// applied (0 when another instance had done it). Throws StoreError when the database's schema is
// newer than this binary's, or when it cannot connect (the message names the host, never the
// password).
int migrate_postgres(const std::string& url);
int postgres_latest_version();

std::unique_ptr<Store> open_postgres_store(const std::string& url, PostgresOptions options = {});

}  // namespace frustum::server
