-- Every figure and table gets a number, so that the prose can point at it and a printed page can be
-- read on its own. Figures count from 1 in the order they appear (the paper's own figures say so in
-- their captions, "The paper's Fig. 2, redrawn"). Tables count from 1 in the main text and as
-- A.1, A.2, ..., B.1, ... in the appendices. A figure with an id, ![...](f.svg){#fig-name}, is referred to as
-- [Fig.](#fig-name), and the link's text becomes its number. Runs after include.lua, so the tables
-- of the included reports are counted too. A link to a figure id that does not exist stops the build,
-- and so does a table without a caption.
local labels = {}
local next_figure, next_table, next_appendix_table = 1, 1, 1
local appendix = nil  -- the letter of the appendix being read, nil in the main text
local heading = ""

local function prefix(caption, label)
  local out = { pandoc.Strong({ pandoc.Str(label) }) }
  if #caption > 0 then out[#out + 1] = pandoc.Space() end
  for _, c in ipairs(caption) do out[#out + 1] = c end
  return out
end

-- The next figure's label, "Fig. N.", remembered under the figure's id for the links to it.
local function next_figure_label(id)
  local label = "Fig. " .. next_figure .. "."
  next_figure = next_figure + 1
  if id ~= "" then labels[id] = label:gsub("%.$", "") end
  return label
end

local function figure(block)
  -- pandoc 3 has a Figure block; pandoc 2 a paragraph holding one captioned image.
  if block.t == "Figure" then
    local label, long = next_figure_label(block.identifier), block.caption.long
    if #long > 0 then long[1].content = prefix(long[1].content, label) end
    return block
  end
  if block.t ~= "Para" or #block.content ~= 1 or block.content[1].t ~= "Image" then return nil end
  local image = block.content[1]
  if #image.caption == 0 then return nil end
  image.caption = prefix(image.caption, next_figure_label(image.identifier))
  return block
end

local function table_block(tbl)
  local label
  if appendix then
    label = "Table " .. appendix .. "." .. next_appendix_table .. "."
    next_appendix_table = next_appendix_table + 1
  else
    label = "Table " .. next_table .. "."
    next_table = next_table + 1
  end
  local long = tbl.caption.long
  -- A caption says what to look at; a section's name does not, so a table without one stops the build
  -- (a report writes its own after the table, "Table: ...").
  if #long == 0 then error("numbering.lua: a table under \"" .. heading .. "\" has no caption") end
  long[1].content = prefix(long[1].content, label)
  return tbl
end

local function number_blocks(blocks)
  for i, b in ipairs(blocks) do
    if b.t == "Header" then
      if b.level == 1 then
        -- Each appendix counts its own tables: B.1 follows A.48, not A.49.
        local letter = b.identifier:match("^appendix%-(%a)")
        if letter and letter:upper() ~= appendix then next_appendix_table = 1 end
        appendix = letter and letter:upper() or nil
      end
      if b.level <= 3 then heading = pandoc.utils.stringify(b.content) end
    elseif b.t == "Table" then
      blocks[i] = table_block(b)
    elseif b.t == "Div" then
      number_blocks(b.content)
    else
      local f = figure(b)
      if f then blocks[i] = f end
    end
  end
end

function Pandoc(doc)
  number_blocks(doc.blocks)
  doc.blocks = doc.blocks:walk({
    Link = function(link)
      local id = link.target:match("^#(fig%-[%w%-]+)$")
      if not id then return nil end
      if not labels[id] then error("numbering.lua: no figure with id " .. id) end
      link.content = { pandoc.Str(labels[id]) }
      return link
    end,
  })
  return doc
end
