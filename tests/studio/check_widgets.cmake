# Fails when a studio source other than widgets.cpp (and path_field.cpp, the path field) calls
# one of ImGui's interactive widgets directly: those bypass the registry, so a duplicate ID among
# them would go unnoticed.
# Variable: DIR (app/studio).
file(GLOB_RECURSE sources "${DIR}/*.cpp" "${DIR}/*.hpp")
set(pattern "ImGui::(Button|SmallButton|ArrowButton|Checkbox|CheckboxFlags|RadioButton|Slider[A-Za-z0-9]*|VSlider[A-Za-z0-9]*|Drag[A-Za-z0-9]*|Input[A-Za-z0-9]*|BeginCombo|Combo|Selectable|TreeNode[A-Za-z]*|CollapsingHeader|InvisibleButton|ImageButton|MenuItem|BeginMenu|ColorEdit[0-9]|ColorPicker[0-9]|ListBox|BeginListBox)\\(")
set(offenders)
foreach(f ${sources})
  get_filename_component(name "${f}" NAME)
  if(name STREQUAL "widgets.cpp" OR name STREQUAL "path_field.cpp")
    continue()
  endif()
  file(STRINGS "${f}" lines REGEX "${pattern}")
  foreach(line ${lines})
    list(APPEND offenders "${name}: ${line}")
  endforeach()
endforeach()
if(offenders)
  string(REPLACE ";" "\n" text "${offenders}")
  message(FATAL_ERROR "Use the registered widgets of widgets.hpp (ui::...) instead of ImGui's:\n${text}")
endif()
message("every interactive widget in ${DIR} goes through widgets.hpp")
