-- Generated tables are spliced in from results/ when the document is built:
--   ::: {include="results/table.md"}
--   :::
-- becomes the Markdown of that file, its headings moved two levels down so that they sit under
-- the section that includes them. A missing file stops the build: the document never shows a
-- table that the build did not make.
function Div(el)
  local path = el.attributes["include"]
  if not path then return nil end
  local f = io.open(path, "r")
  if not f then error("include.lua: cannot open " .. path .. " (run make results first)") end
  local text = f:read("a")
  f:close()
  -- Without smart punctuation: a report that says "--scheme nonlinear" must keep its two dashes.
  local blocks = pandoc.read(text, "markdown-smart").blocks:walk({
    Header = function(h) h.level = math.min(h.level + 2, 6); return h end,
    -- 6.25e-07 must not wrap after its "e-": numbers go in a span the style sheet keeps whole.
    -- A last column of sentences ("why not", "message") beside many columns of numbers would wrap a
    -- word a line: the style sheet gives it room by this class.
    Table = function(t)
      local head = t.head and t.head.rows and t.head.rows[1]
      local last = head and head.cells[#head.cells]
      local name = last and pandoc.utils.stringify(last.contents) or ""
      if name == "why not" or name == "message" then t.attr.classes:insert("text-last") end
      return t
    end,
    Str = function(s)
      if s.text:match("^[<>~%(]?[+%-]?%d[%d%.]*e[+%-]%d+") or s.text:match("^[+%-]%d[%d%.]*") then
        return pandoc.Span({s}, {class = "num"})
      end
    end,
  })
  return pandoc.Div(blocks, {class = "included", ["data-source"] = path})
end
