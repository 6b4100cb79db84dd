# SPDX-License-Identifier: MIT
# A manual page names the documents under docs/ (docs/ratings.md, as the command's --help gives them) by
# where the installed package has them: `cmake -DMAN=PAGE -DDOCDIR=DIR -P man-docs.cmake`, DIR the
# installed docs/ (CMAKE_INSTALL_FULL_DOCDIR, /usr/share/doc/cablesim in the Debian package).
file(READ ${MAN} page)
string(REGEX REPLACE "docs/([a-z\\-]+)\\.md" "${DOCDIR}/\\1.md" page "${page}")
file(WRITE ${MAN} "${page}")
