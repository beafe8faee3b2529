/* The RIB grammar (RISpec App. C), generic over requests: a request is a name followed by
   values (numbers, strings, arrays of either). The actions only hand values to the
   RibFileParser, which checks each finished request against the request table and calls the
   target. A syntax error drops the request it occurs in; parsing resumes at the next request
   name. */

%require "3.2"
%define api.pure full
%define api.prefix {rib}
%define api.token.prefix {RIB_}
%locations
/* Reduce only when the lookahead allows it, so that a bad token drops the request it ends
   instead of letting the request be dispatched first. */
%define lr.default-reduction consistent
%param {yyscan_t scanner}
%parse-param {gonio::RibFileParser& parser}

%code requires {
namespace gonio {
class RibFileParser;
}
typedef void* yyscan_t;
}

%code {
#include "renderer/rib/rib_file_parser.h"

int riblex(RIBSTYPE* value, RIBLTYPE* location, yyscan_t scanner);

static void riberror(RIBLTYPE*, yyscan_t, gonio::RibFileParser& parser, const char*) {
    parser.SyntaxError();
}
}

%union {
    double number;
    int index;
}

%token <number> NUMBER
%token <index> STRING "string"
%token <index> REQUEST "request name"
%token LEX_ERROR

%%

file
    : %empty
    | file request
    ;

request
    : REQUEST { yyerrok; } values { parser.Dispatch($1, @1.first_line, @1.first_column); }
    | error { parser.Discard(); }
    ;

values
    : %empty
    | values value
    ;

value
    : NUMBER { parser.AddNumber($1, @1.first_line, @1.first_column); }
    | STRING { parser.AddString($1, @1.first_line, @1.first_column); }
    | '[' array_items ']' { parser.EndArray(@1.first_line, @1.first_column); }
    ;

array_items
    : %empty { parser.BeginArray(); }
    | array_items NUMBER { parser.ArrayNumber($2); }
    | array_items STRING { parser.ArrayString($2); }
    ;
