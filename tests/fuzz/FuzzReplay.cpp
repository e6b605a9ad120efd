// Replays a fuzz target's corpus (every file under the folders given) through the target, so the
// inputs fuzzing found interesting stay checked in every `make test` with the normal compiler.
#include "FuzzTarget.h"

#include <QDirIterator>
#include <QFile>
#include <QString>

int main(int argc, char* argv[]) {
    long long inputs = 0;
    for (int i = 1; i < argc; ++i) {
        QDirIterator files(QString::fromLocal8Bit(argv[i]), QDir::Files,
                           QDirIterator::Subdirectories);
        while (files.hasNext()) {
            QFile file(files.next());
            if (!file.open(QIODevice::ReadOnly)) {
                std::fprintf(stderr, "cannot read %s\n", qPrintable(file.fileName()));
                return 1;
            }
            const QByteArray bytes = file.readAll();
            LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.constData()),
                                   static_cast<std::size_t>(bytes.size()));
            ++inputs;
        }
    }
    if (inputs == 0) {
        std::fprintf(stderr, "no corpus inputs found\n");
        return 1;
    }
    std::printf("%lld inputs replayed, no property broken\n", inputs);
    return 0;
}
