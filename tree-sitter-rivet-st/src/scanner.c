// External scanner of the Rivet Structured Text grammar.
//
// It recognises what a regular expression cannot: comments, because CODESYS block comments
// `(* … *)` nest, and the words the compiler does not reserve but takes as keywords where the
// text around them says so (`STEP Name:`, `TRANSITION FROM`, a property's `GET` and `SET`).
// It keeps no state between tokens.

#include "tree_sitter/parser.h"

#include <stdbool.h>
#include <stdint.h>

enum TokenType {
  COMMENT,
  STEP_KEYWORD,
  INITIAL_STEP_KEYWORD,
  TRANSITION_KEYWORD,
  GET_KEYWORD,
  SET_KEYWORD,
  ERROR_SENTINEL,
};

// The longest word the scanner needs to compare, plus one to tell a longer word apart.
#define WORD_CAPACITY 16

// OSCAT exports put free text between these two markers; the compiler takes it all as one
// comment, and so do we.
static const char DESCRIPTION_REST[] = "@KEY@:DESCRIPTION*)";
static const char END_DESCRIPTION[] = "(*@KEY@:END_DESCRIPTION*)";

static void advance(TSLexer *lexer) { lexer->advance(lexer, false); }

static void skip(TSLexer *lexer) { lexer->advance(lexer, true); }

static bool is_space(int32_t c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

// Letters, digits and `_`; any non-ASCII character counts as a letter, as in identifiers.
static bool is_word_char(int32_t c) {
  return c == '_' || (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') ||
         (c >= 'A' && c <= 'Z') || c >= 0x80;
}

static bool is_word_start(int32_t c) { return is_word_char(c) && !(c >= '0' && c <= '9'); }

static int32_t to_upper(int32_t c) { return c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c; }

static bool words_equal(const char *word, const char *expected) {
  while (*word && *expected) {
    if (*word++ != *expected++) {
      return false;
    }
  }
  return *word == *expected;
}

// Reads a word into `word` (upper case, truncated so that a longer word never compares
// equal) and returns whether there was one.
static bool read_word(TSLexer *lexer, char word[WORD_CAPACITY + 1]) {
  unsigned length = 0;
  if (!is_word_start(lexer->lookahead)) {
    return false;
  }
  while (is_word_char(lexer->lookahead)) {
    if (length < WORD_CAPACITY) {
      int32_t c = to_upper(lexer->lookahead);
      word[length++] = c < 0x80 ? (char)c : '?';
    }
    advance(lexer);
  }
  word[length] = '\0';
  return true;
}

// The rest of a `(* … *)` comment after its opening, counting nested comments; `true` when it
// closes before the end of the text.
static bool finish_nested_comment(TSLexer *lexer) {
  unsigned depth = 1;
  while (!lexer->eof(lexer)) {
    if (lexer->lookahead == '(') {
      advance(lexer);
      if (lexer->lookahead == '*') {
        advance(lexer);
        depth++;
      }
    } else if (lexer->lookahead == '*') {
      advance(lexer);
      if (lexer->lookahead == ')') {
        advance(lexer);
        if (--depth == 0) {
          return true;
        }
      }
    } else {
      advance(lexer);
    }
  }
  return false;
}

// After `(*`: a nested comment, or an OSCAT description block.
static void finish_parenthesis_comment(TSLexer *lexer) {
  const char *marker = DESCRIPTION_REST;
  while (*marker && lexer->lookahead == *marker) {
    advance(lexer);
    marker++;
  }
  if (*marker) {
    finish_nested_comment(lexer);
    lexer->mark_end(lexer);
    return;
  }
  // The marker alone is a whole comment; it runs on to the end marker if there is one.
  lexer->mark_end(lexer);
  const char *end = END_DESCRIPTION;
  while (!lexer->eof(lexer)) {
    if (lexer->lookahead == *end) {
      advance(lexer);
      end++;
      if (!*end) {
        lexer->mark_end(lexer);
        return;
      }
    } else {
      // The end marker starts with its only '(', so a mismatch restarts the search here.
      end = END_DESCRIPTION;
      if (lexer->lookahead != *end) {
        advance(lexer);
      }
    }
  }
}

// A comment at the lookahead, which is '(' or '/'. Unterminated comments run to the end of
// the text; the compiler reports them.
static bool scan_comment(TSLexer *lexer) {
  if (lexer->lookahead == '(') {
    advance(lexer);
    if (lexer->lookahead != '*') {
      return false;
    }
    advance(lexer);
    finish_parenthesis_comment(lexer);
  } else {
    advance(lexer);
    if (lexer->lookahead == '/') {
      while (!lexer->eof(lexer) && lexer->lookahead != '\n') {
        advance(lexer);
      }
    } else if (lexer->lookahead == '*') {
      advance(lexer);
      for (;;) {
        if (lexer->eof(lexer)) {
          break;
        }
        if (lexer->lookahead == '*') {
          advance(lexer);
          if (lexer->lookahead == '/') {
            advance(lexer);
            break;
          }
        } else {
          advance(lexer);
        }
      }
    } else {
      return false;
    }
    lexer->mark_end(lexer);
  }
  lexer->result_symbol = COMMENT;
  return true;
}

// Looking ahead past a keyword: skips whitespace, comments and pragmas. Returns the first
// significant character; when it is '(' or '/', that character has already been consumed
// (it was not the start of a comment) and `*consumed` is set.
static int32_t next_significant(TSLexer *lexer, bool *consumed) {
  *consumed = false;
  for (;;) {
    while (is_space(lexer->lookahead)) {
      advance(lexer);
    }
    int32_t c = lexer->lookahead;
    if (c == '{') {
      while (!lexer->eof(lexer) && lexer->lookahead != '}') {
        advance(lexer);
      }
      advance(lexer);
    } else if (c == '(') {
      advance(lexer);
      if (lexer->lookahead != '*') {
        *consumed = true;
        return c;
      }
      advance(lexer);
      finish_nested_comment(lexer);
    } else if (c == '/') {
      advance(lexer);
      if (lexer->lookahead == '/') {
        while (!lexer->eof(lexer) && lexer->lookahead != '\n') {
          advance(lexer);
        }
      } else if (lexer->lookahead == '*') {
        advance(lexer);
        for (;;) {
          if (lexer->eof(lexer)) {
            break;
          }
          int32_t inner = lexer->lookahead;
          advance(lexer);
          if (inner == '*' && lexer->lookahead == '/') {
            advance(lexer);
            break;
          }
        }
      } else {
        *consumed = true;
        return c;
      }
    } else {
      return lexer->eof(lexer) ? 0 : c;
    }
  }
}

// After `STEP` or `INITIAL_STEP`: `Name :` (not `:=`) or `Name (` (the step's properties)
// must follow.
static bool step_follows(TSLexer *lexer) {
  bool consumed;
  char word[WORD_CAPACITY + 1];
  next_significant(lexer, &consumed);
  if (consumed || !read_word(lexer, word)) {
    return false;
  }
  int32_t after = next_significant(lexer, &consumed);
  if (after == '(' && consumed) {
    return true;
  }
  if (after != ':' || consumed) {
    return false;
  }
  advance(lexer);
  return lexer->lookahead != '=';
}

// After `TRANSITION`: `FROM`, `Name FROM` or `(` must follow.
static bool transition_follows(TSLexer *lexer) {
  bool consumed;
  char word[WORD_CAPACITY + 1];
  int32_t c = next_significant(lexer, &consumed);
  if (c == '(' && consumed) {
    return true;
  }
  if (consumed || !read_word(lexer, word)) {
    return false;
  }
  if (words_equal(word, "FROM")) {
    return true;
  }
  next_significant(lexer, &consumed);
  return !consumed && read_word(lexer, word) && words_equal(word, "FROM");
}

// After `GET` or `SET`: anything but what makes the word a variable or a call
// (`:=`, `(`, `.`, `[`, `=`, `^`).
static bool accessor_follows(TSLexer *lexer) {
  bool consumed;
  int32_t c = next_significant(lexer, &consumed);
  if (c == '(' && consumed) {
    return false;
  }
  if (c == ':') {
    advance(lexer);
    return lexer->lookahead != '=';
  }
  return c != '.' && c != '[' && c != '=' && c != '^';
}

static bool scan_contextual_keyword(TSLexer *lexer, const bool *valid_symbols) {
  char word[WORD_CAPACITY + 1];
  if (!read_word(lexer, word)) {
    return false;
  }
  lexer->mark_end(lexer);
  if (valid_symbols[STEP_KEYWORD] && words_equal(word, "STEP")) {
    lexer->result_symbol = STEP_KEYWORD;
    return step_follows(lexer);
  }
  if (valid_symbols[INITIAL_STEP_KEYWORD] && words_equal(word, "INITIAL_STEP")) {
    lexer->result_symbol = INITIAL_STEP_KEYWORD;
    return step_follows(lexer);
  }
  if (valid_symbols[TRANSITION_KEYWORD] && words_equal(word, "TRANSITION")) {
    lexer->result_symbol = TRANSITION_KEYWORD;
    return transition_follows(lexer);
  }
  if (valid_symbols[GET_KEYWORD] && words_equal(word, "GET")) {
    lexer->result_symbol = GET_KEYWORD;
    return accessor_follows(lexer);
  }
  if (valid_symbols[SET_KEYWORD] && words_equal(word, "SET")) {
    lexer->result_symbol = SET_KEYWORD;
    return accessor_follows(lexer);
  }
  return false;
}

void *tree_sitter_rivet_st_external_scanner_create(void) { return NULL; }

void tree_sitter_rivet_st_external_scanner_destroy(void *payload) { (void)payload; }

unsigned tree_sitter_rivet_st_external_scanner_serialize(void *payload, char *buffer) {
  (void)payload;
  (void)buffer;
  return 0;
}

void tree_sitter_rivet_st_external_scanner_deserialize(void *payload, const char *buffer,
                                                       unsigned length) {
  (void)payload;
  (void)buffer;
  (void)length;
}

bool tree_sitter_rivet_st_external_scanner_scan(void *payload, TSLexer *lexer,
                                                const bool *valid_symbols) {
  (void)payload;
  while (is_space(lexer->lookahead)) {
    skip(lexer);
  }
  if (lexer->lookahead == '(' || lexer->lookahead == '/') {
    return valid_symbols[COMMENT] && scan_comment(lexer);
  }
  // While recovering from an error every symbol is valid; only comments are safe to scan.
  if (valid_symbols[ERROR_SENTINEL]) {
    return false;
  }
  if (valid_symbols[STEP_KEYWORD] || valid_symbols[INITIAL_STEP_KEYWORD] ||
      valid_symbols[TRANSITION_KEYWORD] || valid_symbols[GET_KEYWORD] ||
      valid_symbols[SET_KEYWORD]) {
    return scan_contextual_keyword(lexer, valid_symbols);
  }
  return false;
}
