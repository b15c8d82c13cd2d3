//! The project's vocabulary, data with tests: dish classes, utensils and motions (`taxonomy`), the state
//! taxonomy with the one start-state rule (`states`), the food taxonomy and aliases (`food_taxonomy`),
//! food knowledge (`foods`) and the listing the app shows (`listing`).

pub mod food_taxonomy;
pub mod foods;
pub mod listing;
pub mod states;
pub mod taxonomy;
