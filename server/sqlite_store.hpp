// The default store: one SQLite file (WAL, synchronous=FULL), writes through one writer thread
// with group commit (sqlite_writer.hpp), reads on a pool of connections.
#pragma once

#include <memory>
#include <string>

#include "server/sqlite_db.hpp"

namespace frustum::server {

std::unique_ptr<Store> open_sqlite_store(const std::string& path,
                                         SqliteSync sync = SqliteSync::Full);

}  // namespace frustum::server
