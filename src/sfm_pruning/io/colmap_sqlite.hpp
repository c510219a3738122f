// A minimal RAII layer over SQLite for the COLMAP database code: every failure becomes an Error
// naming the database file.
#pragma once

#include <sqlite3.h>

#include <cstdint>
#include <string>

namespace sfm_pruning::colmap_sqlite {

class Statement;

class Connection {
 public:
  // Opens an existing file read-only; throws when it is missing or not an SQLite database.
  static Connection OpenReadOnly(const std::string& path);
  // An empty in-memory database; `source` names the eventual file in errors.
  static Connection OpenInMemory(const std::string& source);
  // An in-memory, writable copy of an existing database file (opened read-only, so pending WAL
  // content is included).
  static Connection InMemoryCopyOf(const std::string& path);

  Connection(Connection&& other) noexcept;
  Connection& operator=(Connection&&) = delete;
  Connection(const Connection&) = delete;
  ~Connection();

  void Execute(const std::string& sql);
  Statement Prepare(const std::string& sql);
  bool HasTable(const std::string& table);
  bool HasColumn(const std::string& table, const std::string& column);
  // The whole database as the bytes of a .db file in rollback-journal mode.
  std::string Serialize();

  const std::string& source() const { return source_; }
  [[noreturn]] void Fail(const std::string& what) const;

 private:
  Connection(sqlite3* db, std::string source) : db_(db), source_(std::move(source)) {}
  sqlite3* db_ = nullptr;
  std::string source_;
};

class Statement {
 public:
  Statement(Statement&& other) noexcept;
  Statement(const Statement&) = delete;
  ~Statement();

  // Advances to the next row; false when done.
  bool Step();
  // Runs a statement that returns no rows, then resets it for the next bindings.
  void Run();

  void BindInt64(int index, int64_t value);
  void BindDouble(int index, double value);
  void BindText(int index, const std::string& value);
  void BindBlob(int index, const void* data, size_t size);
  void BindNull(int index);

  int64_t ColumnInt64(int column) const;
  double ColumnDouble(int column) const;
  bool ColumnIsNull(int column) const;
  std::string ColumnText(int column) const;
  // Raw blob bytes (empty for NULL).
  std::string ColumnBlob(int column) const;

 private:
  friend class Connection;
  Statement(sqlite3_stmt* stmt, const Connection* connection) : stmt_(stmt), connection_(connection) {}
  sqlite3_stmt* stmt_ = nullptr;
  const Connection* connection_ = nullptr;
};

// Throws "<file>: not a COLMAP database: table 'X' is missing" unless `db` has every table
// common to COLMAP's 3.x and 4.x schemas.
void RequireColmapTables(Connection& db);

}  // namespace sfm_pruning::colmap_sqlite
