/* The shading-language grammar (RISpec 3.2 App. B, with the precedences Aqsis and Pixie use).
   The actions only build the syntax tree (ast.h); meaning is checked by typecheck.cpp. */

%require "3.0"
%define api.pure full
%define api.prefix {sl}
%define parse.error verbose
%define api.location.type {gonio::sl::SourceLoc}
%locations
%param {void* scanner}
%parse-param {gonio::sl::ParseState* state}

/* Statements that begin with a type name are declarations (or a nested function) before they
   are casts: `float x;` declares x, `float f() {...}` defines f. Bison resolves the 5 shift/
   reduce and 4 reduce/reduce conflicts this leaves towards the declaration (shift, and the
   earlier rule); CMake passes -Wno-conflicts-sr -Wno-conflicts-rr for them. */

%code requires {
#include <string>
#include "shaderlang/compiler/ast.h"
namespace gonio::sl { struct ParseState; }
}

%code {
#include <algorithm>
#include <cstddef>
#include <cstring>
#include <memory>
#include <type_traits>

#include "shaderlang/compiler/gather_loop.h"
#include "shaderlang/compiler/parse_state.h"

#define YYLLOC_DEFAULT(Current, Rhs, N)            \
    do {                                           \
        if (N) (Current) = YYRHSLOC(Rhs, 1);       \
        else (Current) = YYRHSLOC(Rhs, 0);         \
    } while (0)

int sllex(SLSTYPE* value, SLLTYPE* location, void* scanner);

namespace {
using gonio::sl::Node;
using gonio::sl::NodeKind;

void slerror(SLLTYPE* location, void*, gonio::sl::ParseState* state, const char* message) {
    state->Error(*location, message);
}

// Bison's C parser grows its stacks in C++ only through a user's yyoverflow: without one it
// stops at 200 entries ("memory exhausted": an if / else if chain of 33 did). Its states,
// values and locations are plain data, so each stack grows by copying into a buffer the parse
// state keeps until the parse ends.
static_assert(std::is_trivially_copyable_v<SLSTYPE> && std::is_trivially_copyable_v<SLLTYPE>);
constexpr std::ptrdiff_t kMaxParserDepth = 100000;

template <class T>
T* GrownStack(gonio::sl::ParseState* state, const T* stack, std::size_t bytes, std::ptrdiff_t size) {
    auto& buffer = state->parserStacks.emplace_back(new char[std::size_t(size) * sizeof(T)]);
    std::memcpy(buffer.get(), stack, bytes);
    return reinterpret_cast<T*>(buffer.get());
}

template <class S, class V, class L>
void GrowParserStacks(gonio::sl::ParseState* state, S** states, std::size_t statesBytes, V** values,
                      std::size_t valuesBytes, L** locations, std::size_t locationsBytes,
                      std::ptrdiff_t* size) {
    if (*size >= kMaxParserDepth) {
        state->Error((*locations)[locationsBytes / sizeof(L) - 1],
                     "the shader nests more deeply than " + std::to_string(kMaxParserDepth) +
                         " levels of the grammar");
        return;  // the stacks stay full: the parser stops
    }
    const std::ptrdiff_t grown = std::min(2 * *size, kMaxParserDepth);
    *states = GrownStack(state, *states, statesBytes, grown);
    *values = GrownStack(state, *values, valuesBytes, grown);
    *locations = GrownStack(state, *locations, locationsBytes, grown);
    *size = grown;
}

#define yyoverflow(message, states, statesBytes, values, valuesBytes, locations, locationsBytes, \
                   size)                                                                       \
    GrowParserStacks(state, states, statesBytes, values, valuesBytes, locations, locationsBytes, \
                     size)

Node* Make(gonio::sl::ParseState* state, NodeKind kind, const gonio::sl::SourceLoc& loc,
           std::initializer_list<Node*> kids = {}) {
    Node* n = state->tree->Make(kind, loc);
    n->kids.assign(kids.begin(), kids.end());
    return n;
}

Node* Name(gonio::sl::ParseState* state, NodeKind kind, const gonio::sl::SourceLoc& loc,
           std::string* text) {
    Node* n = state->tree->Make(kind, loc);
    n->name = std::move(*text);
    delete text;
    return n;
}

// Declarations share a type prefix; each declared variable gets a copy of it.
// Array lengths are whole numbers up to 2^20 (larger ones are surely mistakes).
int ArrayLength(gonio::sl::ParseState* state, const gonio::sl::SourceLoc& loc, float number) {
    if (!(number >= 1 && number <= float(1 << 20)) || number != float(int(number))) {
        state->Error(loc, "array length must be a positive integer");
        return 1;
    }
    return int(number);
}

// break n / continue n: n is a small whole number.
int LoopLevel(gonio::sl::ParseState* state, const gonio::sl::SourceLoc& loc, float number) {
    if (!(number >= 1 && number <= 1000) || number != float(int(number))) {
        state->Error(loc, "the loop level of break and continue must be a positive integer");
        return 1;
    }
    return int(number);
}

// NAME(args) { ... }: only gather takes a statement after its arguments.
Node* GatherStatement(gonio::sl::ParseState* state, const gonio::sl::SourceLoc& loc,
                      std::string* name, Node* args, Node* hit, Node* miss) {
    const bool gather = *name == "gather";
    const std::string text = *name;
    delete name;
    if (!gather) {
        state->Error(loc, "'" + text + "(...)' cannot be followed by a block (only gather() can)");
        return nullptr;
    }
    return gonio::sl::MakeGatherLoop(state, loc, args, hit, miss);
}

void ApplyPrefix(Node* list, const Node* prefix) {
    for (Node* v : list->kids) {
        int length = v->declType.arrayLength;
        v->declType = prefix->declType;
        v->declType.arrayLength = length;
        v->detail = prefix->detail;
        v->hasDetail = prefix->hasDetail;
        v->output = prefix->output;
        v->isExtern = prefix->isExtern;
    }
}
}  // namespace
}

%union {
    float number;
    std::string* text;
    gonio::sl::Node* node;
    int value;
}

%destructor { delete $$; } <text>

%token <number> NUMBER
%token <text> IDENT STRINGLIT
%token SURFACE LIGHT DISPLACEMENT VOLUME IMAGER TRANSFORMATION
%token FLOAT STRING COLOR POINT VECTOR NORMAL MATRIX VOID
%token UNIFORM VARYING OUTPUT EXTERN
%token IF ELSE WHILE FOR BREAK CONTINUE RETURN ILLUMINANCE ILLUMINATE SOLAR
%token EQ NE LE GE AND OR ADD_ASSIGN SUB_ASSIGN MUL_ASSIGN DIV_ASSIGN
%token LEX_ERROR

%type <value> shader_type type_kw assign_op
%type <node> formals formal_groups formal_group formal_defs formal_def qualifiers
%type <node> stmts stmt block decl_stmt defs def init expr primary args arg_list opt_expr
%type <node> function_def elements cast_operand
%type <number> opt_level

%right '=' ADD_ASSIGN SUB_ASSIGN MUL_ASSIGN DIV_ASSIGN
%right '?' ':'
%left OR
%left AND
%left EQ NE
%left '<' '>' LE GE
%left '+' '-'
%left '^'
%left '*' '/'
%left '.'
%precedence UMINUS '!'
%precedence LOWER_THAN_ELSE
%precedence ELSE

%start file

%%

file
    : %empty
    | file definition
    ;

definition
    : shader_type IDENT '(' formals ')' block {
          Node* n = Name(state, NodeKind::ShaderDef, @2, $2);
          n->op = $1;
          n->kids = {$4, $6};
          state->tree->definitions.push_back(n);
      }
    | function_def { state->tree->definitions.push_back($1); }
    | error '}'
    ;

shader_type
    : SURFACE { $$ = 0; } | LIGHT { $$ = 1; } | DISPLACEMENT { $$ = 2; }
    | VOLUME { $$ = 3; } | IMAGER { $$ = 4; } | TRANSFORMATION { $$ = 5; }
    ;

function_def
    : type_kw IDENT '(' formals ')' block {
          $$ = Name(state, NodeKind::FunctionDef, @2, $2);
          $$->declType.base = gonio::sl::BaseType($1);
          $$->kids = {$4, $6};
      }
    | qualifiers type_kw IDENT '(' formals ')' block {
          $$ = Name(state, NodeKind::FunctionDef, @3, $3);
          $$->declType.base = gonio::sl::BaseType($2);
          $$->detail = $1->detail;
          $$->hasDetail = $1->hasDetail;
          $$->kids = {$5, $7};
      }
    | VOID IDENT '(' formals ')' block {
          $$ = Name(state, NodeKind::FunctionDef, @2, $2);
          $$->kids = {$4, $6};
      }
    ;

type_kw
    : FLOAT { $$ = int(gonio::sl::BaseType::Float); }
    | STRING { $$ = int(gonio::sl::BaseType::String); }
    | COLOR { $$ = int(gonio::sl::BaseType::Color); }
    | POINT { $$ = int(gonio::sl::BaseType::Point); }
    | VECTOR { $$ = int(gonio::sl::BaseType::Vector); }
    | NORMAL { $$ = int(gonio::sl::BaseType::Normal); }
    | MATRIX { $$ = int(gonio::sl::BaseType::Matrix); }
    ;

/* output, extern, uniform, varying in any order before the type. */
qualifiers
    : UNIFORM { $$ = Make(state, NodeKind::List, @1); $$->detail = gonio::sl::Detail::Uniform;
                $$->hasDetail = true; }
    | VARYING { $$ = Make(state, NodeKind::List, @1); $$->hasDetail = true; }
    | OUTPUT { $$ = Make(state, NodeKind::List, @1); $$->output = true; }
    | EXTERN { $$ = Make(state, NodeKind::List, @1); $$->isExtern = true; }
    | qualifiers UNIFORM { $$ = $1; $$->detail = gonio::sl::Detail::Uniform; $$->hasDetail = true; }
    | qualifiers VARYING { $$ = $1; $$->detail = gonio::sl::Detail::Varying; $$->hasDetail = true; }
    | qualifiers OUTPUT { $$ = $1; $$->output = true; }
    | qualifiers EXTERN { $$ = $1; $$->isExtern = true; }
    ;

formals
    : %empty { $$ = Make(state, NodeKind::List, @$); }
    | formal_groups { $$ = $1; }
    | formal_groups ';' { $$ = $1; }
    ;

formal_groups
    : formal_group { $$ = $1; }
    | formal_groups ';' formal_group { $$ = $1; for (Node* k : $3->kids) $$->kids.push_back(k); }
    ;

formal_group
    : type_kw formal_defs {
          Node* prefix = Make(state, NodeKind::List, @1);
          prefix->declType.base = gonio::sl::BaseType($1);
          ApplyPrefix($2, prefix);
          $$ = $2;
      }
    | qualifiers type_kw formal_defs {
          $1->declType.base = gonio::sl::BaseType($2);
          ApplyPrefix($3, $1);
          $$ = $3;
      }
    ;

formal_defs
    : formal_def { $$ = Make(state, NodeKind::List, @1, {$1}); }
    | formal_defs ',' formal_def { $$ = $1; $$->kids.push_back($3); }
    ;

formal_def
    : def { $$ = $1; }
    | IDENT '[' ']' {
          $$ = Name(state, NodeKind::VarDecl, @1, $1);
          $$->declType.arrayLength = gonio::sl::TypeSpec::kUnsized;
          $$->kids = {nullptr};
      }
    | IDENT '[' ']' '=' init {
          $$ = Name(state, NodeKind::VarDecl, @1, $1);
          $$->declType.arrayLength = gonio::sl::TypeSpec::kUnsized;
          $$->kids = {$5};
      }
    ;

def
    : IDENT { $$ = Name(state, NodeKind::VarDecl, @1, $1); $$->kids = {nullptr}; }
    | IDENT '=' init { $$ = Name(state, NodeKind::VarDecl, @1, $1); $$->kids = {$3}; }
    | IDENT '[' NUMBER ']' {
          $$ = Name(state, NodeKind::VarDecl, @1, $1);
          $$->declType.arrayLength = ArrayLength(state, @3, $3);
          $$->kids = {nullptr};
      }
    | IDENT '[' NUMBER ']' '=' init {
          $$ = Name(state, NodeKind::VarDecl, @1, $1);
          $$->declType.arrayLength = ArrayLength(state, @3, $3);
          $$->kids = {$6};
      }
    ;

init
    : expr { $$ = $1; }
    | '{' elements '}' { $$ = $2; $$->loc = @1; }
    ;

elements
    : expr { $$ = Make(state, NodeKind::InitList, @1, {$1}); }
    | elements ',' expr { $$ = $1; $$->kids.push_back($3); }
    ;

block
    : '{' stmts '}' { $$ = $2; $$->loc = @1; }
    ;

stmts
    : %empty { $$ = Make(state, NodeKind::Block, @$); }
    | stmts stmt { $$ = $1; if ($2) $$->kids.push_back($2); }
    ;

stmt
    : decl_stmt { $$ = $1; }
    | function_def { $$ = $1; }
    | expr ';' { $$ = Make(state, NodeKind::ExprStmt, @1, {$1}); }
    | ';' { $$ = nullptr; }
    | block { $$ = $1; }
    | IF '(' expr ')' stmt %prec LOWER_THAN_ELSE { $$ = Make(state, NodeKind::If, @1, {$3, $5, nullptr}); }
    | IF '(' expr ')' stmt ELSE stmt { $$ = Make(state, NodeKind::If, @1, {$3, $5, $7}); }
    | WHILE '(' expr ')' stmt { $$ = Make(state, NodeKind::While, @1, {$3, $5}); }
    | FOR '(' opt_expr ';' opt_expr ';' opt_expr ')' stmt {
          $$ = Make(state, NodeKind::For, @1, {$3, $5, $7, $9});
      }
    | BREAK opt_level ';' { $$ = Make(state, NodeKind::Break, @1); $$->op = LoopLevel(state, @2, $2); }
    | CONTINUE opt_level ';' { $$ = Make(state, NodeKind::Continue, @1); $$->op = LoopLevel(state, @2, $2); }
    | RETURN opt_expr ';' { $$ = Make(state, NodeKind::Return, @1, {$2}); }
    | ILLUMINANCE '(' arg_list ')' stmt {
          $$ = $3; $$->kind = NodeKind::Illuminance; $$->loc = @1; $$->kids.push_back($5);
      }
    | ILLUMINATE '(' arg_list ')' stmt {
          $$ = $3; $$->kind = NodeKind::Illuminate; $$->loc = @1; $$->kids.push_back($5);
      }
    /* gather(...) { } [else stmt]: "gather" is no keyword (shaders name things gather), and a
       block after a call's ')' cannot continue an expression, so this is unambiguous. */
    | IDENT '(' args ')' block %prec LOWER_THAN_ELSE { $$ = GatherStatement(state, @1, $1, $3, $5, nullptr); }
    | IDENT '(' args ')' block ELSE stmt { $$ = GatherStatement(state, @1, $1, $3, $5, $7); }
    | SOLAR '(' args ')' stmt {
          $$ = $3; $$->kind = NodeKind::Solar; $$->loc = @1; $$->kids.push_back($5);
      }
    | error ';' { $$ = nullptr; }
    | error '}' { $$ = nullptr; }
    ;

opt_level
    : %empty { $$ = 1; }
    | NUMBER { $$ = $1; }
    ;

opt_expr
    : %empty { $$ = nullptr; }
    | expr { $$ = $1; }
    ;

decl_stmt
    : type_kw defs ';' {
          Node* prefix = Make(state, NodeKind::List, @1);
          prefix->declType.base = gonio::sl::BaseType($1);
          ApplyPrefix($2, prefix);
          $$ = $2;
      }
    | qualifiers type_kw defs ';' {
          $1->declType.base = gonio::sl::BaseType($2);
          ApplyPrefix($3, $1);
          $$ = $3;
      }
    ;

defs
    : def { $$ = Make(state, NodeKind::Block, @1, {$1}); }
    | defs ',' def { $$ = $1; $$->kids.push_back($3); }
    ;

args
    : %empty { $$ = Make(state, NodeKind::Call, @$); }
    | arg_list { $$ = $1; }
    ;

arg_list
    : expr { $$ = Make(state, NodeKind::Call, @1, {$1}); }
    | arg_list ',' expr { $$ = $1; $$->kids.push_back($3); }
    ;

assign_op
    : '=' { $$ = '='; } | ADD_ASSIGN { $$ = '+'; } | SUB_ASSIGN { $$ = '-'; }
    | MUL_ASSIGN { $$ = '*'; } | DIV_ASSIGN { $$ = '/'; }
    ;

expr
    : primary { $$ = $1; }
    | expr assign_op expr %prec '=' { $$ = Make(state, NodeKind::Assign, @2, {$1, $3}); $$->op = $2; }
    | expr '?' expr ':' expr { $$ = Make(state, NodeKind::Ternary, @2, {$1, $3, $5}); }
    | expr OR expr { $$ = Make(state, NodeKind::Binary, @2, {$1, $3}); $$->op = gonio::sl::kOpOr; }
    | expr AND expr { $$ = Make(state, NodeKind::Binary, @2, {$1, $3}); $$->op = gonio::sl::kOpAnd; }
    | expr EQ expr { $$ = Make(state, NodeKind::Binary, @2, {$1, $3}); $$->op = gonio::sl::kOpEq; }
    | expr NE expr { $$ = Make(state, NodeKind::Binary, @2, {$1, $3}); $$->op = gonio::sl::kOpNe; }
    | expr '<' expr { $$ = Make(state, NodeKind::Binary, @2, {$1, $3}); $$->op = '<'; }
    | expr '>' expr { $$ = Make(state, NodeKind::Binary, @2, {$1, $3}); $$->op = '>'; }
    | expr LE expr { $$ = Make(state, NodeKind::Binary, @2, {$1, $3}); $$->op = gonio::sl::kOpLe; }
    | expr GE expr { $$ = Make(state, NodeKind::Binary, @2, {$1, $3}); $$->op = gonio::sl::kOpGe; }
    | expr '+' expr { $$ = Make(state, NodeKind::Binary, @2, {$1, $3}); $$->op = '+'; }
    | expr '-' expr { $$ = Make(state, NodeKind::Binary, @2, {$1, $3}); $$->op = '-'; }
    | expr '^' expr { $$ = Make(state, NodeKind::Binary, @2, {$1, $3}); $$->op = '^'; }
    | expr '*' expr { $$ = Make(state, NodeKind::Binary, @2, {$1, $3}); $$->op = '*'; }
    | expr '/' expr { $$ = Make(state, NodeKind::Binary, @2, {$1, $3}); $$->op = '/'; }
    | expr '.' expr { $$ = Make(state, NodeKind::Binary, @2, {$1, $3}); $$->op = '.'; }
    | '-' expr %prec UMINUS { $$ = Make(state, NodeKind::Unary, @1, {$2}); $$->op = '-'; }
    | '+' expr %prec UMINUS { $$ = $2; }
    | '!' expr { $$ = Make(state, NodeKind::Unary, @1, {$2}); $$->op = '!'; }
    | type_kw cast_operand {
          $$ = Make(state, NodeKind::Cast, @1, {$2});
          $$->declType.base = gonio::sl::BaseType($1);
      }
    | type_kw STRINGLIT cast_operand {
          $$ = Make(state, NodeKind::Cast, @1, {$3});
          $$->declType.base = gonio::sl::BaseType($1);
          $$->name = std::move(*$2);
          delete $2;
      }
    ;

cast_operand
    : primary { $$ = $1; }
    | '-' cast_operand { $$ = Make(state, NodeKind::Unary, @1, {$2}); $$->op = '-'; }
    | type_kw cast_operand { $$ = Make(state, NodeKind::Cast, @1, {$2}); $$->declType.base = gonio::sl::BaseType($1); }
    ;

primary
    : NUMBER { $$ = Make(state, NodeKind::Number, @1); $$->number = $1; }
    | STRINGLIT { $$ = Name(state, NodeKind::String, @1, $1); }
    | IDENT { $$ = Name(state, NodeKind::Identifier, @1, $1); }
    | IDENT '(' args ')' { $$ = $3; $$->name = std::move(*$1); delete $1; $$->loc = @1; }
    /* Message passing (RISpec §15.8): surface() and displacement() share their names with
       shader types. */
    | SURFACE '(' args ')' { $$ = $3; $$->name = "surface"; $$->loc = @1; }
    | DISPLACEMENT '(' args ')' { $$ = $3; $$->name = "displacement"; $$->loc = @1; }
    | primary '[' expr ']' { $$ = Make(state, NodeKind::Index, @2, {$1, $3}); }
    | '(' expr ')' { $$ = $2; }
    | '(' expr ',' arg_list ')' {
          $$ = $4; $$->kind = NodeKind::Tuple; $$->loc = @1;
          $$->kids.insert($$->kids.begin(), $2);
      }
    ;

%%
