#include "classcycles.h"

#include <QtCore/QHash>
#include <QtCore/QSet>

#include <algorithm>

namespace mbscope::testdocs {

namespace {

QString classOf(const QString &file)
{
    const qsizetype dot = file.lastIndexOf(QLatin1Char('.'));
    return dot > file.lastIndexOf(QLatin1Char('/')) ? file.left(dot) : file;
}

// Tarjan's strongly connected components, iterative so that a long chain does not exhaust the stack.
class Components
{
public:
    explicit Components(const QMap<QString, QStringList> &graph) : m_graph(graph) {}

    QList<QStringList> run()
    {
        for (auto it = m_graph.cbegin(); it != m_graph.cend(); ++it) {
            if (!m_index.contains(it.key()))
                visit(it.key());
        }
        std::sort(m_found.begin(), m_found.end());
        return m_found;
    }

private:
    struct Frame {
        QString node;
        qsizetype next = 0;
    };

    void open(const QString &node, QList<Frame> &frames)
    {
        m_index.insert(node, m_counter);
        m_low.insert(node, m_counter);
        ++m_counter;
        m_stack.append(node);
        m_onStack.insert(node);
        frames.append({node, 0});
    }

    void visit(const QString &root)
    {
        QList<Frame> frames;
        open(root, frames);
        while (!frames.isEmpty()) {
            Frame &top = frames.last();
            const QStringList edges = m_graph.value(top.node);
            if (top.next < edges.size()) {
                const QString to = edges.at(top.next++);
                if (!m_index.contains(to))
                    open(to, frames);
                else if (m_onStack.contains(to))
                    m_low[top.node] = std::min(m_low.value(top.node), m_index.value(to));
                continue;
            }
            const QString node = top.node;
            frames.removeLast();
            if (!frames.isEmpty())
                m_low[frames.last().node] = std::min(m_low.value(frames.last().node), m_low.value(node));
            if (m_low.value(node) != m_index.value(node))
                continue;
            QStringList component;
            QString member;
            do {
                member = m_stack.takeLast();
                m_onStack.remove(member);
                component.append(member);
            } while (member != node);
            if (component.size() > 1) {
                component.sort();
                m_found.append(component);
            }
        }
    }

    const QMap<QString, QStringList> &m_graph;
    QHash<QString, int> m_index;
    QHash<QString, int> m_low;
    QStringList m_stack;
    QSet<QString> m_onStack;
    QList<QStringList> m_found;
    int m_counter = 0;
};

} // namespace

QList<QStringList> classCycles(const QMap<QString, QStringList> &includes)
{
    QMap<QString, QStringList> graph;
    for (auto it = includes.cbegin(); it != includes.cend(); ++it) {
        const QString from = classOf(it.key());
        QStringList &edges = graph[from];
        for (const QString &file : it.value()) {
            const QString to = classOf(file);
            if (to != from && !edges.contains(to))
                edges.append(to);
        }
    }
    return Components(graph).run();
}

} // namespace mbscope::testdocs
