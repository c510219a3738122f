#include "sfm_pruning/io/colmap_sqlite.hpp"

#include <filesystem>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning::colmap_sqlite {

namespace {

sqlite3* OpenOrThrow(const std::string& filename, int flags, const std::string& source) {
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(filename.c_str(), &db, flags, nullptr) != SQLITE_OK) {
    const std::string message = db ? sqlite3_errmsg(db) : "out of memory";
    sqlite3_close(db);
    throw FileError(source, "cannot open database: " + message);
  }
  return db;
}

}  // namespace

Connection Connection::OpenReadOnly(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw FileError(path, "file not found");
  Connection connection(OpenOrThrow(path, SQLITE_OPEN_READONLY, path), path);
  // sqlite3_open_v2 is lazy: the header is only checked by the first query, which is where a
  // non-database file reports "file is not a database".
  connection.Execute("SELECT count(*) FROM sqlite_master");
  return connection;
}

Connection Connection::OpenInMemory(const std::string& source) {
  return Connection(OpenOrThrow(":memory:", SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, source), source);
}

Connection Connection::InMemoryCopyOf(const std::string& path) {
  Connection source = OpenReadOnly(path);
  Connection copy = OpenInMemory(path);
  sqlite3_backup* backup = sqlite3_backup_init(copy.db_, "main", source.db_, "main");
  if (backup == nullptr) copy.Fail("cannot copy database");
  const int rc = sqlite3_backup_step(backup, -1);
  sqlite3_backup_finish(backup);
  if (rc != SQLITE_DONE) copy.Fail("cannot copy database");
  return copy;
}

Connection::Connection(Connection&& other) noexcept : db_(other.db_), source_(std::move(other.source_)) {
  other.db_ = nullptr;
}

Connection::~Connection() { sqlite3_close(db_); }

void Connection::Fail(const std::string& what) const {
  throw FileError(source_, what + ": " + sqlite3_errmsg(db_));
}

void Connection::Execute(const std::string& sql) {
  Statement statement = Prepare(sql);
  while (statement.Step()) {
  }
}

Statement Connection::Prepare(const std::string& sql) {
  sqlite3_stmt* stmt = nullptr;
  if (sqlite3_prepare_v2(db_, sql.c_str(), -1, &stmt, nullptr) != SQLITE_OK) {
    sqlite3_finalize(stmt);
    Fail("SQL error");
  }
  return Statement(stmt, this);
}

bool Connection::HasTable(const std::string& table) {
  Statement statement = Prepare("SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = ?");
  statement.BindText(1, table);
  return statement.Step();
}

bool Connection::HasColumn(const std::string& table, const std::string& column) {
  // PRAGMA arguments cannot be bound; table names here are the library's own constants.
  Statement statement = Prepare("PRAGMA table_info(" + table + ")");
  while (statement.Step()) {
    if (statement.ColumnText(1) == column) return true;
  }
  return false;
}

std::string Connection::Serialize() {
  sqlite3_int64 size = 0;
  unsigned char* data = sqlite3_serialize(db_, "main", &size, 0);
  if (data == nullptr) Fail("cannot serialize database");
  std::string bytes(reinterpret_cast<const char*>(data), static_cast<size_t>(size));
  sqlite3_free(data);
  // Header bytes 18 and 19 (file format write/read version) are 2 for WAL mode, kept from a WAL
  // source by the backup. A standalone file must not claim WAL: 1 is rollback-journal mode, which
  // also lets readers open it read-only in read-only folders.
  if (bytes.size() >= 20) bytes[18] = bytes[19] = 1;
  return bytes;
}

Statement::Statement(Statement&& other) noexcept : stmt_(other.stmt_), connection_(other.connection_) {
  other.stmt_ = nullptr;
}

Statement::~Statement() { sqlite3_finalize(stmt_); }

bool Statement::Step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  connection_->Fail("SQL error");
}

void Statement::Run() {
  while (Step()) {
  }
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
}

void Statement::BindInt64(int index, int64_t value) { sqlite3_bind_int64(stmt_, index, value); }
void Statement::BindDouble(int index, double value) { sqlite3_bind_double(stmt_, index, value); }
void Statement::BindText(int index, const std::string& value) {
  sqlite3_bind_text(stmt_, index, value.c_str(), static_cast<int>(value.size()), SQLITE_TRANSIENT);
}
void Statement::BindBlob(int index, const void* data, size_t size) {
  sqlite3_bind_blob64(stmt_, index, data, size, SQLITE_TRANSIENT);
}
void Statement::BindNull(int index) { sqlite3_bind_null(stmt_, index); }

int64_t Statement::ColumnInt64(int column) const { return sqlite3_column_int64(stmt_, column); }
double Statement::ColumnDouble(int column) const { return sqlite3_column_double(stmt_, column); }
bool Statement::ColumnIsNull(int column) const { return sqlite3_column_type(stmt_, column) == SQLITE_NULL; }
std::string Statement::ColumnText(int column) const {
  const unsigned char* text = sqlite3_column_text(stmt_, column);
  return text ? std::string(reinterpret_cast<const char*>(text)) : std::string();
}
std::string Statement::ColumnBlob(int column) const {
  const void* data = sqlite3_column_blob(stmt_, column);
  const int size = sqlite3_column_bytes(stmt_, column);
  return data ? std::string(static_cast<const char*>(data), static_cast<size_t>(size)) : std::string();
}

void RequireColmapTables(Connection& db) {
  for (const char* table :
       {"cameras", "images", "keypoints", "descriptors", "matches", "two_view_geometries"}) {
    if (!db.HasTable(table)) {
      throw FileError(db.source(), std::string("not a COLMAP database: table '") + table + "' is missing");
    }
  }
}

}  // namespace sfm_pruning::colmap_sqlite
