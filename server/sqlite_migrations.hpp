// The SQLite store's schema as numbered, forward-only migrations embedded in the binary
// (migration i brings the schema from version i to i + 1; none is ever edited once released).
#pragma once

#include "server/sqlite_db.hpp"

namespace frustum::server {

// Applies the missing migrations in one exclusive transaction, so that of several processes
// opening the database at once exactly one migrates and the others find it done. Throws
// StoreError when the database's schema is newer than this binary's.
void migrate_sqlite(SqliteDb& db, const std::string& path);
int sqlite_schema_version(SqliteDb& db);
int sqlite_latest_version();

}  // namespace frustum::server
