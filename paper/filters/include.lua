-- Generated tables are spliced in from results/ when the document is built, with their words put in:
--   ::: {include="results/table.md"}
--   :::
-- becomes the Markdown of that file, its headings moved two levels down so that they sit under
-- the section that includes them. A missing file stops the build: the document never shows a
-- table that the build did not make.
-- The reports are plain text first (read in a terminal, grepped, diffed), so they write their few
-- symbols in ASCII: eps, lambda_1h, m12, +-, <=. In the document they stand beside MathML, so each
-- such word is set as the mathematics it names. Only whole words are taken, with brackets and
-- punctuation around them kept, so "epsilon" or an option in code ("--eps") is left alone.
local ascii_math = {
  ["eps"] = "\\varepsilon", ["w_eps"] = "w_\\varepsilon", ["eps^-1"] = "\\varepsilon^{-1}",
  ["lambda"] = "\\lambda", ["lambda_1"] = "\\lambda_1", ["lambda_1h"] = "\\lambda_{1h}", ["1/lambda_1h"] = "1/\\lambda_{1h}",
  ["m12"] = "m_{12}", ["phi"] = "\\varphi", ["xi"] = "\\xi", ["pi"] = "\\pi", ["theta"] = "\\theta",
  ["rho"] = "\\rho", ["nu"] = "\\nu", ["w_c"] = "w_c", ["w_free"] = "w_{\\mathrm{free}}",
  ["C^1"] = "C^1", ["Lap^2"] = "\\Delta^2", ["S^T"] = "S^T",
}
-- and any one letter to a numeric power: h^2, h^-4, N^1.02.
local function power(word)
  local base, exponent = word:match("^(%a)%^(%-?%d[%d%.]*)$")
  if base then return base .. "^{" .. exponent:gsub("%.$", "") .. "}" end
end
local ascii_symbol = { ["+-"] = "±", ["<="] = "≤", [">="] = "≥", ["->"] = "→" }

-- Words with brackets of their own, taken whole (with trailing punctuation).
local ascii_whole = { ["q(pi/4)"] = "q(\\pi/4)", ["max|m12|"] = "\\max\\lvert m_{12}\\rvert" }

local function as_math(s)
  local before, symbol, after = s.text:match("^(%(?)([<>+%-][=%->])(.*)$")
  if symbol and ascii_symbol[symbol] then return pandoc.Str(before .. ascii_symbol[symbol] .. after) end
  local whole, tail = s.text:match("^(.-)([,.;:]*)$")
  if ascii_whole[whole] then
    local out = { pandoc.Math("InlineMath", ascii_whole[whole]) }
    if tail ~= "" then out[2] = pandoc.Str(tail) end
    return out
  end
  local open, word, rest = s.text:match("^([%(]*)([%w_%^%-%./]+)(.*)$")
  if not word then return nil end
  -- A word's own trailing full stop or comma is punctuation, not part of it.
  while word ~= "" and not ascii_math[word] and not power(word) and word:match("[%.%-/]$") do
    rest = word:sub(-1) .. rest
    word = word:sub(1, -2)
  end
  local tex = ascii_math[word] or power(word)
  if not tex or rest:match("^[%w_]") then
    -- A symbol inside a call, max(phi, 0): set what follows the bracket.
    local call, inner = s.text:match("^([%w_]+%()(.+)$")
    local set = inner and as_math(pandoc.Str(inner))
    if not set then return nil end
    if set.t == "Str" then set = { set } end
    table.insert(set, 1, pandoc.Str(call))
    return set
  end
  local out = {}
  if open ~= "" then out[#out + 1] = pandoc.Str(open) end
  out[#out + 1] = pandoc.Math("InlineMath", tex)
  if rest ~= "" then out[#out + 1] = pandoc.Str(rest) end
  return out
end

-- The blocks under the heading named `name` (to the next heading of its level or above), and the
-- blocks outside that section. The heading itself is in neither: the including document names it.
local function split_section(blocks, name, path)
  local inside, outside, level, done = pandoc.List(), pandoc.List(), nil, false
  for _, b in ipairs(blocks) do
    if b.t == "Header" and level and not done and b.level <= level then done = true end
    if b.t == "Header" and not level and pandoc.utils.stringify(b.content) == name then
      level = b.level
    elseif level and not done then
      inside:insert(b)
    else
      outside:insert(b)
    end
  end
  if not level then error("include.lua: " .. path .. " has no section \"" .. name .. "\"") end
  return inside, outside
end

function Div(el)
  local path = el.attributes["include"]
  if not path then return nil end
  -- Opened here only to stop with this message, which names the remedy, before render_report's own.
  local f = io.open(path, "r")
  if not f then error("include.lua: cannot open " .. path .. " (run make results first)") end
  f:close()
  -- The report's captions and sentences are markers; build/render_report puts in their words from
  -- reports/words.md (one place, which a terminal reader's render_report also reads). A marker it
  -- cannot render stops the build.
  local text = pandoc.pipe(os.getenv("RENDER_REPORT") or "build/render_report", {path}, "")
  -- Without smart punctuation: a report that says "--scheme nonlinear" must keep its two dashes.
  local blocks = pandoc.read(text, "markdown-smart").blocks
  local section, except = el.attributes["section"], el.attributes["except"]
  if section then blocks = split_section(blocks, section, path) end
  if except then blocks = select(2, split_section(blocks, except, path)) end
  -- pandoc 2.17's plain lists cannot walk: a Div around the blocks can.
  if section or except then blocks = pandoc.Div(blocks):walk({}).content end
  blocks = blocks:walk({
    Header = function(h) h.level = math.min(h.level + 2, 6); return h end,
    -- A last column of sentences (the bad-input table's "message") beside other columns would wrap a
    -- word a line: the style sheet gives it room by this class.
    Table = function(t)
      local head = t.head and t.head.rows and t.head.rows[1]
      local last = head and head.cells[#head.cells]
      local name = last and pandoc.utils.stringify(last.contents) or ""
      if name == "message" then t.attr.classes:insert("text-last") end
      -- Nine columns or more of numbers fill a printed page at the reports' size: the style sheet
      -- sets them smaller in print, so that Chromium need not shrink every page to fit one table.
      if #t.colspecs >= 9 then t.attr.classes:insert("wide") end
      -- A long table may run on to the next page; a short one is kept whole, with its caption.
      local rows = 0
      for _, body in ipairs(t.bodies) do rows = rows + #body.body end
      if rows > 15 then t.attr.classes:insert("long") end
      return t
    end,
    -- A symbol the reports write in ASCII is set as mathematics; 6.25e-07 must not wrap after its
    -- "e-": numbers go in a span the style sheet keeps whole.
    Str = function(s)
      local math = as_math(s)
      if math then return math end
      if s.text:match("^[<>~%(]?[+%-]?%d[%d%.]*e[+%-]%d+") or s.text:match("^[+%-]%d[%d%.]*") then
        return pandoc.Span({s}, {class = "num"})
      end
    end,
  })
  -- "64 x 64", "1.01 x the sag": a lone x after a number is a times sign.
  blocks = blocks:walk({
    Inlines = function(inlines)
      for i = 3, #inlines do
        local x, before = inlines[i], inlines[i - 2]
        if x.t == "Str" and x.text == "x" and inlines[i - 1].t == "Space" then
          local number = before.t == "Str" and before.text or before.t == "Span" and pandoc.utils.stringify(before) or ""
          if number:match("%d$") then inlines[i] = pandoc.Str("×") end
        end
      end
      return inlines
    end,
  })
  return pandoc.Div(blocks, {class = "included", ["data-source"] = path})
end
