//! `Edit::ReplaceChart`: a CFC or SFC body replaced as a whole, the one edit behind every
//! change a chart editor makes.

use crate::edit::{EditError, TextTarget};
use crate::network_splice::body_mut;
use crate::validate::chart_problems;
use crate::{Body, Edit, Folder};

/// Replaces the CFC or SFC body `target` with `body` (of the same language) and returns the
/// edit that puts the old one back.
///
/// The new chart must keep its language's structural rules; a chart that breaks one is
/// refused and nothing changes, so a saved chart always loads again.
pub(crate) fn replace_chart(
    root: &mut Folder,
    target: TextTarget,
    body: Body,
) -> Result<Edit, EditError> {
    let current = body_mut(root, &target)?;
    let same_language = matches!(
        (&*current, &body),
        (Body::Cfc { .. }, Body::Cfc { .. }) | (Body::Sfc { .. }, Body::Sfc { .. })
    );
    if !same_language {
        return Err(EditError::NotChart(target.to_string()));
    }
    if let Some(problem) = chart_problems(&body).into_iter().next() {
        return Err(EditError::InvalidObject(format!("{target}: {problem}")));
    }
    let old = std::mem::replace(current, body);
    Ok(Edit::ReplaceChart {
        target,
        body: Box::new(old),
    })
}

#[cfg(test)]
mod tests {
    use crate::{
        Body, CfcChart, Edit, EditError, Folder, Node, Object, Pou, PouKind, Project, SfcChart,
        TextTarget,
    };

    fn project_with(body: Body) -> Project {
        Project {
            application: Folder {
                name: String::new(),
                children: vec![Node::Object(Object::Pou(Pou {
                    name: "Seq".into(),
                    kind: PouKind::Program,
                    return_type: None,
                    extends: None,
                    implements: Vec::new(),
                    comment: String::new(),
                    variables: Vec::new(),
                    body,
                    methods: Vec::new(),
                    properties: Vec::new(),
                    actions: Vec::new(),
                    transitions: Vec::new(),
                }))],
            },
            ..Project::default()
        }
    }

    fn body_of(project: &Project) -> &Body {
        match project.application.object("Seq") {
            Some(Object::Pou(pou)) => &pou.body,
            _ => panic!("no POU"),
        }
    }

    #[test]
    fn a_chart_is_replaced_and_the_inverse_puts_the_old_one_back() {
        let mut project = project_with(Body::Sfc {
            chart: SfcChart::new_body(),
        });
        let mut renamed = SfcChart::new_body();
        if let Some(crate::SfcNode::Transition(transition)) = renamed.sequence.get_mut(1) {
            transition.condition = "xStart".into();
        }
        let new = Body::Sfc { chart: renamed };
        let inverse = Edit::ReplaceChart {
            target: TextTarget::Pou("Seq".into()),
            body: Box::new(new.clone()),
        }
        .apply(&mut project)
        .unwrap();
        assert_eq!(body_of(&project), &new);
        inverse.apply(&mut project).unwrap();
        assert_eq!(
            body_of(&project),
            &Body::Sfc {
                chart: SfcChart::new_body()
            }
        );
    }

    #[test]
    fn a_chart_that_breaks_a_rule_is_refused_naming_the_element() {
        let mut project = project_with(Body::Sfc {
            chart: SfcChart::new_body(),
        });
        let mut broken = SfcChart::new_body();
        broken.sequence.pop();
        let refused = Edit::ReplaceChart {
            target: TextTarget::Pou("Seq".into()),
            body: Box::new(Body::Sfc { chart: broken }),
        }
        .apply(&mut project);
        assert_eq!(
            refused,
            Err(EditError::InvalidObject(
                "'Seq': element 2: the chart must end with a jump (or an alternative branch \
                 whose every branch ends with a jump)"
                    .into()
            ))
        );
    }

    #[test]
    fn a_chart_of_another_language_is_refused() {
        let mut project = project_with(Body::Sfc {
            chart: SfcChart::default(),
        });
        let refused = Edit::ReplaceChart {
            target: TextTarget::Pou("Seq".into()),
            body: Box::new(Body::Cfc {
                chart: CfcChart::default(),
            }),
        }
        .apply(&mut project);
        assert_eq!(refused, Err(EditError::NotChart("'Seq'".into())));
    }

    #[test]
    fn a_transition_object_s_text_is_edited_and_listed_with_its_file() {
        let mut project = project_with(Body::Sfc {
            chart: SfcChart::new_body(),
        });
        if let Some(Object::Pou(pou)) = project.application.object_mut("Seq") {
            pou.transitions.push(crate::PouAction {
                name: "Ready".into(),
                body: Body::st("a AND b"),
            });
        }
        let target = TextTarget::Transition {
            pou: "Seq".into(),
            transition: "Ready".into(),
        };
        Edit::ReplaceText {
            target: target.clone(),
            range: 0..1,
            text: "x".into(),
        }
        .apply(&mut project)
        .unwrap();
        let bodies = crate::st_body_files(&project);
        let listed: Vec<_> = bodies
            .iter()
            .map(|body| (body.file.clone(), body.target.clone(), body.text))
            .collect();
        assert_eq!(
            listed,
            [(
                std::path::PathBuf::from("application/Seq.Ready.st"),
                target,
                "x AND b"
            )]
        );
        let missing = Edit::ReplaceText {
            target: TextTarget::Transition {
                pou: "Seq".into(),
                transition: "Gone".into(),
            },
            range: 0..0,
            text: String::new(),
        }
        .apply(&mut project);
        assert_eq!(
            missing,
            Err(EditError::NoSuchMember {
                pou: "Seq".into(),
                what: "transition",
                name: "Gone".into()
            })
        );
    }
}
