#pragma once
// The review server's secrets, all through libsodium: passwords as Argon2id strings (the string
// carries its own parameters), session and API tokens as 32 random bytes shown once and stored
// only as their BLAKE2b digest, and SHA-256 content hashes of uploaded files.

#include <cstddef>
#include <string>
#include <string_view>

namespace mtcs::serve {

// Argon2id at libsodium's interactive limits (64 MiB, 2 passes): ~0.16 s on this project's
// 2-core machine, which is why the server hashes at most two at a time.
std::string hash_password(std::string_view password);
bool verify_password(const std::string& stored, std::string_view password);

// 64 hex digits of fresh randomness: a session cookie, a CSRF token or an API token.
std::string random_token();
// What the store keeps of a token: its BLAKE2b-256 digest in hex, so a copy of the database
// opens no session.
std::string token_digest(std::string_view token);
// Constant-time equality of two strings of equal length (false when the lengths differ).
bool same_secret(std::string_view a, std::string_view b);

// SHA-256 of a byte stream, fed in pieces.
class Sha256 {
 public:
  Sha256();
  void add(const char* data, std::size_t size);
  std::string hex();  // ends the stream

 private:
  alignas(64) unsigned char state_[128];
};

}  // namespace mtcs::serve
