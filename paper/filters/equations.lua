-- Equation numbers for MathML output. Pandoc 2.17 drops \tag{} when it writes MathML, so a
-- display equation written $$ ... \tag{5a} $$ loses its number. We take the tag out of the
-- TeX and put it back as text beside the equation, with the anchor #eq-5a to link to.
-- A tag used twice stops the build.
local seen = {}

function Math(el)
  if el.mathtype ~= "DisplayMath" then return nil end
  local tag = el.text:match("\\tag{([^}]*)}")
  if not tag then return nil end
  if seen[tag] then error("equations.lua: equation (" .. tag .. ") is numbered twice") end
  seen[tag] = true
  local body = el.text:gsub("\\tag{[^}]*}", "")
  return pandoc.Span({pandoc.Math("DisplayMath", body), pandoc.Span({pandoc.Str("(" .. tag .. ")")}, {class = "eqno"})},
                     {id = "eq-" .. tag, class = "equation"})
end
