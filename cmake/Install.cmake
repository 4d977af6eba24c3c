# Installation and package config: placeholder, completed by the install work.
